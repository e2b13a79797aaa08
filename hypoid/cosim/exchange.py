"""The gear FMU and a vehicle FMU, both in Model Exchange, integrated as one ODE (no coupling step
at all): the connections of hypoid.cosim.master.GearVehicle (the vehicle's T_hs to the gear's
T_w, the gear's w_w to the vehicle's w_w) made at every evaluation of the right-hand side, the
propeller-shaft torque T_s a function of time given by the caller. CVODE of fmpy (BDF, the
FMUs' nominals, root finding on the gear's event indicators) through hypoid.fmu.exchange.

    m = GearVehicleExchange(gear_fmu, vehicle_fmu, gear_start, vehicle_start, torque)
    gear, vehicle = m.run(t_end, output_interval, gear_out, vehicle_out)

gear and vehicle are structured arrays (a 'time' field and the named outputs), as
hypoid.fmu.instance.Instance.series gives."""

from hypoid.cosim.master import Pair
from hypoid.fmu.exchange import Exchange, ExchangeInstance


class GearVehicleExchange(Pair):
    """Two Model Exchange instances, `gear` and `vehicle`, started with their start values and
    the inputs of the connections consistent at the start; torque(t) the gear's T_s [N m]."""

    def __init__(self, gear_fmu, vehicle_fmu, gear_start, vehicle_start, torque, rtol=1e-6):
        self.torque = torque
        self.gear = ExchangeInstance(gear_fmu, name="gear")
        self.vehicle = ExchangeInstance(vehicle_fmu, name="vehicle")
        self.g_in = self.gear.refs(["T_s", "T_w"])
        self.g_ww = self.gear.refs(["w_w"])
        self.k_ww = self.gear.state_index("w_w")  # a state of the gear: read where it is
        self.v_in = self.vehicle.refs(["w_w"])
        self.v_ths = self.vehicle.refs(["T_hs"])
        self.gear.start({**gear_start, "T_s": torque(0.0)})
        self.vehicle.start({**vehicle_start, "w_w": self.gear.get_reals(self.g_ww)[0]})
        self.set_g_in, self.set_v_in = self.gear.real_setter(self.g_in), \
            self.vehicle.real_setter(self.v_in)
        self.get_v_ths = self.vehicle.real_getter(self.v_ths)
        self.exchange = Exchange([self.gear, self.vehicle], rtol=rtol, couple=self._couple)
        self._couple(0.0, [self.gear.states()])

    def _couple(self, t, states):
        """The connections at time t, with the states the integrator set: w_w (a state of the
        gear) to the vehicle, whose T_hs (its states and that input) goes to the gear."""
        self.set_v_in([float(states[0][self.k_ww])])
        T_hs = self.get_v_ths()[0]
        self.set_g_in([self.torque(t), T_hs])

    def run(self, t_end, output_interval, gear_out, vehicle_out):
        return self.exchange.run(t_end, output_interval, [list(gear_out), list(vehicle_out)])

    @property
    def events(self):
        return self.exchange.events
