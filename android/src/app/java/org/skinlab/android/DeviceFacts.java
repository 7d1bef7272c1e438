package org.skinlab.android;

import java.io.ByteArrayOutputStream;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.function.Supplier;

import android.app.Activity;
import android.content.pm.PackageInfo;
import android.content.pm.PackageManager;
import android.os.Build;

import org.skinlab.android.logic.CpuName;
import org.skinlab.internal.bench.DeviceResults;

/**
 * What the device file says about the phone and the app, as Android reports it: {@code Build}'s
 * names, the ABIs, the CPU ({@link CpuName}: {@code Build.SOC_MODEL} from API 31, else
 * {@code /proc/cpuinfo}, else {@code Build.HARDWARE}), the display's refresh rate, the package's
 * version.
 */
final class DeviceFacts {
    /** More than any {@code /proc/cpuinfo} holds (a few kB per core). */
    private static final int CPUINFO_BYTES = 1 << 16;

    private DeviceFacts() {
    }

    /**
     * The device, for the measuring thread: what needs the UI thread (the display) is read now, the
     * CPU's file when the supplier is asked.
     */
    @SuppressWarnings("deprecation") // getDefaultDisplay: its successor, Context.getDisplay, needs API 30 (min is 26)
    static Supplier<DeviceResults.Device> of(Activity activity) {
        double refreshHz = activity.getWindowManager().getDefaultDisplay().getRefreshRate();
        String socManufacturer = Build.VERSION.SDK_INT >= 31 ? Build.SOC_MANUFACTURER : null;
        String socModel = Build.VERSION.SDK_INT >= 31 ? Build.SOC_MODEL : null;
        String manufacturer = Build.MANUFACTURER;
        String model = Build.MODEL;
        String device = Build.DEVICE;
        String release = Build.VERSION.RELEASE;
        int sdk = Build.VERSION.SDK_INT;
        String[] abis = Build.SUPPORTED_ABIS;
        String hardware = Build.HARDWARE;
        return () -> new DeviceResults.Device(manufacturer, model, device, release, sdk, Arrays.asList(abis),
                CpuName.of(Runtime.getRuntime().availableProcessors(), socManufacturer, socModel, cpuinfo(), hardware),
                refreshHz);
    }

    /** The app's package and version, as its manifest gives them. */
    @SuppressWarnings("deprecation") // versionCode: getLongVersionCode needs API 28 (min is 26)
    static DeviceResults.App app(Activity activity) {
        try {
            PackageInfo info = activity.getPackageManager().getPackageInfo(activity.getPackageName(), 0);
            long code = Build.VERSION.SDK_INT >= 28 ? info.getLongVersionCode() : info.versionCode;
            return new DeviceResults.App(activity.getPackageName(), info.versionName != null ? info.versionName
                    : "unknown", code);
        } catch (PackageManager.NameNotFoundException e) {
            return new DeviceResults.App(activity.getPackageName(), "unknown", 0);
        }
    }

    /** The text of {@code /proc/cpuinfo}, or null where it cannot be read. */
    private static String cpuinfo() {
        try (InputStream in = new FileInputStream("/proc/cpuinfo")) {
            ByteArrayOutputStream text = new ByteArrayOutputStream();
            byte[] buffer = new byte[4096];
            for (int n; (n = in.read(buffer)) > 0 && text.size() < CPUINFO_BYTES;) {
                text.write(buffer, 0, n);
            }
            return new String(text.toByteArray(), StandardCharsets.UTF_8);
        } catch (IOException | SecurityException e) {
            return null;
        }
    }
}
