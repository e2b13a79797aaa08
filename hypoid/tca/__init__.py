"""Tooth contact data: the surrogate TCA of the paper's gear sets (`surrogate`, `loaded`), a
user's TCA table (`table`), the Fourier fit (`fit`), gear-set files (`gearset_file`) and the
files the `hypoid tca` command writes (`gearsets`)."""
