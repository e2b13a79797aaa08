import java.io.File;
import java.util.Locale;

import no.ntnu.ihb.fmi4j.FmiStatus;
import no.ntnu.ihb.fmi4j.importer.fmi2.CoSimulationSlave;
import no.ntnu.ihb.fmi4j.importer.fmi2.Fmu;
import no.ntnu.ihb.fmi4j.modeldescription.variables.Causality;
import no.ntnu.ihb.fmi4j.modeldescription.variables.ModelVariables;
import no.ntnu.ihb.fmi4j.modeldescription.variables.TypedScalarVariable;
import no.ntnu.ihb.fmi4j.modeldescription.variables.VariableType;

/**
 * Loads an FMI 2.0 co-simulation FMU with FMI4j, sets the given start values, steps it with a
 * fixed communication step and prints every Real and Integer output at the end, one
 * "name value" a line.
 *
 *   java Fmi4jCheck FMU STOP_TIME STEP [name=value ...]
 *
 * Exit status 1 when a call fails.
 */
public final class Fmi4jCheck {

    private static void check(boolean ok, String what) {
        if (!ok) {
            System.err.println("fmi4j: " + what + " failed");
            System.exit(1);
        }
    }

    private static void check(FmiStatus status, String what) {
        check(status == FmiStatus.OK, what + " (" + status + ")");
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 3) {
            System.err.println("usage: Fmi4jCheck FMU STOP_TIME STEP [name=value ...]");
            System.exit(2);
        }
        double stop = Double.parseDouble(args[1]);
        double h = Double.parseDouble(args[2]);
        try (Fmu fmu = Fmu.from(new File(args[0]))) {
            CoSimulationSlave slave = fmu.asCoSimulationFmu().newInstance("fmi4j");
            ModelVariables vars = slave.getModelVariables();
            check(slave.setupExperiment(0.0, stop, 0.0), "fmi2SetupExperiment");
            for (int i = 3; i < args.length; i++) {
                String[] kv = args[i].split("=", 2);
                TypedScalarVariable<?> v = vars.getByName(kv[0]);
                long[] vr = {v.getValueReference()};
                if (v.getType() == VariableType.REAL) {
                    check(slave.writeReal(vr, new double[] {Double.parseDouble(kv[1])}), "set " + kv[0]);
                } else {
                    check(slave.writeInteger(vr, new int[] {Integer.parseInt(kv[1])}), "set " + kv[0]);
                }
            }
            check(slave.enterInitializationMode(), "fmi2EnterInitializationMode");
            check(slave.exitInitializationMode(), "fmi2ExitInitializationMode");
            long n = Math.round(stop / h);
            for (long k = 0; k < n; k++) {
                check(slave.doStep(k * h, h), "fmi2DoStep at t = " + k * h);
            }
            System.out.println("# " + fmu.getModelName() + " through FMI4j: " + n + " steps of " + h + " s");
            for (TypedScalarVariable<?> v : vars.getByCausality(Causality.OUTPUT)) {
                long[] vr = {v.getValueReference()};
                if (v.getType() == VariableType.REAL) {
                    double[] value = new double[1];
                    check(slave.readReal(vr, value), "get " + v.getName());
                    System.out.println(v.getName() + " " + String.format(Locale.ROOT, "%.17g", value[0]));
                } else if (v.getType() == VariableType.INTEGER) {
                    int[] value = new int[1];
                    check(slave.readInteger(vr, value), "get " + v.getName());
                    System.out.println(v.getName() + " " + value[0]);
                }
            }
            check(slave.terminate(), "fmi2Terminate");
            slave.close();
        }
    }
}
