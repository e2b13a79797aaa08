"""Co-simulation masters of the gear FMU and a vehicle FMU: the package's own (`master`, fmpy),
libcosim's (`libcosim`) and Ecos' (`ecos`)."""
