package org.skinlab.android.logic;

import java.util.Locale;

import org.skinlab.internal.bench.DeviceResults;

/**
 * The CPU's name for the device file, from the best source a phone has: the SoC's maker and model
 * ({@code Build.SOC_MANUFACTURER} and {@code SOC_MODEL}, API 31 and later), else a name line of
 * {@code /proc/cpuinfo} ("Hardware" on ARM kernels that list it, "model name" on x86), else
 * {@code Build.HARDWARE} (often the board's code name); null when none names anything.
 */
public final class CpuName {
    /** What Android reports where it does not know. */
    private static final String UNKNOWN = "unknown";

    private CpuName() {
    }

    /**
     * The CPU with {@code cores} cores, named from {@code socManufacturer} and {@code socModel}
     * (null below API 31), the text of {@code /proc/cpuinfo} (null when unreadable) or
     * {@code hardware}.
     */
    public static DeviceResults.Cpu of(int cores, String socManufacturer, String socModel, String cpuinfo,
            String hardware) {
        if (known(socModel)) {
            String name = known(socManufacturer) ? socManufacturer.trim() + " " + socModel.trim() : socModel.trim();
            return new DeviceResults.Cpu(cores, name, "Build.SOC_MODEL");
        }
        String fromCpuinfo = cpuinfo == null ? null : fromCpuinfo(cpuinfo);
        if (fromCpuinfo != null) {
            return new DeviceResults.Cpu(cores, fromCpuinfo, "/proc/cpuinfo");
        }
        if (known(hardware)) {
            return new DeviceResults.Cpu(cores, hardware.trim(), "Build.HARDWARE");
        }
        return new DeviceResults.Cpu(cores, null, null);
    }

    /** The value of the first "Hardware" line of {@code /proc/cpuinfo}, else of "model name"; null without either. */
    static String fromCpuinfo(String text) {
        String hardware = field(text, "hardware");
        return hardware != null ? hardware : field(text, "model name");
    }

    private static String field(String text, String name) {
        for (String line : text.split("\n")) {
            int colon = line.indexOf(':');
            if (colon > 0 && line.substring(0, colon).trim().toLowerCase(Locale.ROOT).equals(name)) {
                String value = line.substring(colon + 1).trim();
                if (known(value)) {
                    return value;
                }
            }
        }
        return null;
    }

    private static boolean known(String s) {
        return s != null && !s.isBlank() && !s.trim().equalsIgnoreCase(UNKNOWN);
    }
}
