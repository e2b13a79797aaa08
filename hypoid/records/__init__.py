"""Generated records: blocks of the documentation written from recorded data (`docblocks`)."""
