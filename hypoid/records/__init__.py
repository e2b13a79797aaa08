"""Records: every measured figure of the project (costs, errors, measured losses, step counts)
kept once, in docs/records/, as a data file and a page written from it. `registry` lists them,
one module per kind of page writes them, `cli` is `hypoid records`; the measuring scripts live
in bench/, tools/ and tests/cosim/ (they need the built FMU) and write the data."""
