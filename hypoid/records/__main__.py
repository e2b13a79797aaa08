"""`python -m hypoid.records`: the same as `hypoid records`."""

import sys

from hypoid.cli import main

sys.exit(main(["records", *sys.argv[1:]]))
