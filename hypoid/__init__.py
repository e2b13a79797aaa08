"""HypoidGearPair: tools around the lubricated hypoid gear pair FMU (data, sweeps, plots)."""

__version__ = "0.1.0"
