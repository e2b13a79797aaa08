"""What the drivers of outside co-simulation hosts share (libcosim.py, ecos.py): whether the
host's library loads here, the error that says how to get it, the integer-coded gear FMU both
need, and the gear and vehicle scene run in either host's fixed-step algorithm (GearVehicle)."""

import pathlib

from hypoid.errors import UsageError


def why_not(probe):
    """None when probe() (which loads the host's library) runs, else why not (one line)."""
    try:
        probe()
    except Exception as e:  # noqa: BLE001 - any failure means: not usable here
        return f"{type(e).__name__}: {e}"
    return None


def require(host, why, install):
    """Raises UsageError naming the host, why it does not load (why: its why_unavailable) and
    how to install it."""
    reason = why()
    if reason:
        raise UsageError(f"{host} is not usable here ({reason}): {install}")


def intenum_fmu(fmu, host="the host"):
    """The integer-coded variant that the build writes next to the FMU (libcosim and Ecos
    ignore Enumerations)."""
    fmu = pathlib.Path(fmu)
    path = fmu.with_name(f"{fmu.stem}_intenum.fmu")
    if not path.exists():
        raise UsageError(f"{path} is missing: {host} needs the integer-coded FMU the build "
                         "writes next to the FMU")
    return path


class GearVehicle:
    """hypoid.cosim.master.GearVehicle's scene in an outside host's fixed-step (Jacobi)
    algorithm: `Execution` is the driver's class (hypoid.cosim.libcosim.Execution or
    hypoid.cosim.ecos.Execution, which take the same calls), the gear FMU its integer-coded
    variant; T_hs -> T_w and w_w -> w_w are the host's connections, the callers' inputs are set
    before each step and held over it. step() returns the outputs after the step.

    A host that reads outputs after passing the connections' values on (Ecos:
    Execution.reads_after_transfer) would give the vehicle's outputs with direct feedthrough from
    w_w (its speed v and T_hs) at the gear's new wheel speed, a step ahead of the other masters'.
    There the gear's w_w goes to the vehicle as the caller's inputs do, set before each step, so
    that every host returns the same outputs."""

    def __init__(self, Execution, gear_fmu, vehicle_fmu, gear_start, vehicle_start, h,
                 gear_out, vehicle_out, gear_inputs=("T_s",), vehicle_inputs=()):
        from hypoid.fmu.values import TABLE

        self.ex = Execution(h)
        try:
            self.ex.add("gear", intenum_fmu(gear_fmu, Execution.host))
            self.ex.add("vehicle", vehicle_fmu)
            self.ex.initial("gear", {var.name: x for var, x in TABLE.fmu_values(gear_start)})
            self.ex.initial("vehicle", vehicle_start)
            self.ex.connect("vehicle", "T_hs", "gear", "T_w")
            self.vehicle_inputs = list(vehicle_inputs)
            if Execution.reads_after_transfer:
                self.vehicle_inputs.insert(0, "w_w")
                self.w_w = self.ex.reals("gear", [self.ex.ref("gear", "w_w")])
            else:
                self.ex.connect("gear", "w_w", "vehicle", "w_w")
                self.w_w = []
            self.g_refs = [self.ex.ref("gear", x) for x in gear_out]
            self.v_refs = [self.ex.ref("vehicle", x) for x in vehicle_out]
        except BaseException:
            self.ex.close()
            raise
        self.gear_out, self.vehicle_out = list(gear_out), list(vehicle_out)
        self.gear_inputs = list(gear_inputs)
        self.i_ww = self.gear_out.index("w_w")

    def step(self, t=None, h=None, gear_inputs=(), vehicle_inputs=()):
        """One step of the execution's own size (t and h as the fmpy master takes them, unused)."""
        if self.gear_inputs:
            self.ex.set_reals("gear", self.gear_inputs, gear_inputs)
        if self.vehicle_inputs:
            self.ex.set_reals("vehicle", self.vehicle_inputs, [*self.w_w, *vehicle_inputs])
        self.ex.step()
        gear = self.ex.reals("gear", self.g_refs)
        if self.w_w:
            self.w_w = [gear[self.i_ww]]
        return gear, self.ex.reals("vehicle", self.v_refs)

    def close(self):
        self.ex.close()
