package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.bench.DeviceResults;

/** The CPU's name from the best source a phone has, on texts in the forms kernels write. */
class CpuNameTest {
    /** An ARM kernel that names the SoC (older Qualcomm and Exynos kernels). */
    private static final String ARM_WITH_HARDWARE = "processor\t: 0\nBogoMIPS\t: 38.40\nFeatures\t: fp asimd\n"
            + "CPU implementer\t: 0x51\n\nprocessor\t: 1\nBogoMIPS\t: 38.40\n\nHardware\t: Qualcomm Technologies, Inc SDM845\n";
    /** A newer ARM kernel: per-core fields only. */
    private static final String ARM_WITHOUT = "processor\t: 0\nBogoMIPS\t: 26.00\nFeatures\t: fp asimd evtstrm\n"
            + "CPU implementer\t: 0x41\nCPU part\t: 0xd05\n";
    /** An x86 emulator. */
    private static final String X86 = "processor\t: 0\nvendor_id\t: GenuineIntel\nmodel name\t: Intel(R) Core(TM) i7-8700"
            + " CPU @ 3.20GHz\n";

    @Test
    void theSocModelComesFirstFromApi31() {
        assertEquals(new DeviceResults.Cpu(8, "QTI SM8250", "Build.SOC_MODEL"),
                CpuName.of(8, "QTI", "SM8250", ARM_WITH_HARDWARE, "qcom"));
        assertEquals(new DeviceResults.Cpu(8, "SM8250", "Build.SOC_MODEL"),
                CpuName.of(8, "unknown", "SM8250", null, "qcom"));
    }

    @Test
    void belowItTheKernelsNameThenTheBoard() {
        assertEquals(new DeviceResults.Cpu(8, "Qualcomm Technologies, Inc SDM845", "/proc/cpuinfo"),
                CpuName.of(8, null, null, ARM_WITH_HARDWARE, "qcom"));
        assertEquals(new DeviceResults.Cpu(4, "Intel(R) Core(TM) i7-8700 CPU @ 3.20GHz", "/proc/cpuinfo"),
                CpuName.of(4, "unknown", "unknown", X86, "ranchu"));
        assertEquals(new DeviceResults.Cpu(8, "mt6765", "Build.HARDWARE"), CpuName.of(8, null, null, ARM_WITHOUT,
                "mt6765"));
        assertEquals(new DeviceResults.Cpu(8, "mt6765", "Build.HARDWARE"), CpuName.of(8, null, null, null, "mt6765"));
    }

    @Test
    void nothingNamedIsNull() {
        assertEquals(new DeviceResults.Cpu(2, null, null), CpuName.of(2, null, null, ARM_WITHOUT, "unknown"));
        assertEquals(new DeviceResults.Cpu(2, null, null), CpuName.of(2, "", " ", "Hardware\t: \n", null));
    }
}
