"""HypoidGearPair: tools around the lubricated hypoid gear pair FMU (data, sweeps, plots), in
sub-packages by layer (docs/python.md)."""

__version__ = "0.1.0"
