"""The axle in a car over a speed cycle (`hypoid drive-cycle`)."""
