"""Studies of the FMU: one scenario (`scenario`), steady-state points and continuation sweeps
(`steady`, `metrics`, `continuation`, `sweep`, `results`), the paper's studies (`paper`) with
their tables, findings, figures and report (`tables`, `findings`, `regime`, `modes`, `plots`,
`report`)."""
