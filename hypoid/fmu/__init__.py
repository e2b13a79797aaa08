"""FMU access: the one instance class (`instance.Instance`), values by name (`values`), the
generated variable table (`variables`), the fidelity levels and solvers (`levels`), and FMU
instances in worker processes (`parallel`)."""
