"""The car around the axle (its parameters for the vehicle FMU) and its driver."""

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Vehicle:
    """A mid-size passenger car (the vehicle FMU's defaults, docs/cosimulation.md); v_eps is
    wider than the FMU's default so that the rolling resistance and brakes stay smooth over a
    long communication step at standstill (docs/axle.md)."""
    m: float = 1500.0        # kg
    r_dyn: float = 0.3       # m
    J_wheels: float = 3.0    # kg m^2
    c_rr: float = 0.012
    CdA: float = 0.7         # m^2
    rho_air: float = 1.2     # kg/m^3
    k_hs: float = 1.2e4      # N m/rad, both half-shafts and tyres
    v_eps: float = 0.5       # m/s
    v_rest: float = 1e-6     # m/s: below it the car stands (3.6 mm an hour; docs/axle.md)
    air_factor: float = 0.5  # air speed over the housing / vehicle speed (assumed)

    def fmu_values(self):
        return {"m": self.m, "r_dyn": self.r_dyn, "J_wheels": self.J_wheels, "c_rr": self.c_rr,
                "CdA": self.CdA, "rho_air": self.rho_air, "k_hs": self.k_hs,
                "v_eps": self.v_eps, "coupling": 2.0}

    def road_force(self, v):
        return (self.c_rr * self.m * 9.81 * math.tanh(v / self.v_eps)
                + 0.5 * self.rho_air * self.CdA * v * abs(v))


@dataclass
class Driver:
    """Speed tracking: feed-forward of the cycle's acceleration and road load, PI on the speed
    error; negative demand goes to engine braking (down to T_s_min) and then to the brakes."""
    vehicle: Vehicle
    ratio: float             # N_g / N_p
    J_wheel: float           # all inertia referred to the wheel [kg m^2]
    k_p: float = 1.0         # 1/s
    k_i: float = 0.1         # 1/s^2
    T_s_max: float = 600.0   # N m at the propeller shaft
    T_s_min: float = -20.0   # engine braking at the propeller shaft, in gear (v > 3 m/s)
    integral: float = field(default=0.0, init=False)

    def command(self, v_now, v_next, v, h):
        """(T_s, T_brake) for the step towards v_next (the cycle's speed at the step's end)."""
        veh, r = self.vehicle, self.vehicle.r_dyn
        if v_next <= 0.0 and v < 0.3:
            self.integral = 0.0
            return 0.0, 300.0  # standing: no drive, brakes held
        e = v_now - v
        self.integral = float(np.clip(self.integral + e * h, -2.0, 2.0))
        a = (v_next - v_now) / h + self.k_p * e + self.k_i * self.integral
        T_wheel = self.J_wheel / r * a + r * veh.road_force(v_now)
        T_s = T_wheel / self.ratio
        floor = self.T_s_min if v > 3.0 else 0.0
        if T_s >= floor:
            return min(T_s, self.T_s_max), 0.0
        return floor, floor * self.ratio - T_wheel

