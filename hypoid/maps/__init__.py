"""Maps of the FMU's steady states: efficiency maps for the map level (`effmap`) and the axle's
loss map (`lossmap`)."""
