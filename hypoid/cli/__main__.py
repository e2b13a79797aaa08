"""`python -m hypoid.cli`: the `hypoid` command where its console script is not on the PATH."""
import sys

from hypoid.cli import main

sys.exit(main())
