"""Records: every measured figure of the project (costs, errors, measured losses, step counts)
kept once, in docs/records/, as a data file and a page written from it. `registry` lists them,
one module per kind of page writes them, `writer` writes and checks the pages and the docs
index's list (the command line: `hypoid records`, hypoid.cli.records); the measuring scripts live
in bench/, tools/ and tests/cosim/ (they need the built FMU) and write the data."""
