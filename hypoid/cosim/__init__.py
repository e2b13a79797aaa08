"""Co-simulation masters: the libcosim driver (`libcosim`)."""
