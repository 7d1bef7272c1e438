package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import com.fasterxml.jackson.databind.JsonNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The phone section's part of the report ({@link EvalPhoneSection}), from its results alone: the
 * thesis' Galaxy S7 Edge; the phones added (what they are, their CPU's time per frame beside this
 * machine's scalar kernels, what that leaves one character at 60 Hz, their GPU's frames per second
 * against copies beside the thesis' figure) or, before any, which numbers no phone has produced.
 * Every number through {@link EvalReport#num}; every text a phone reports in a code span.
 */
final class EvalPhoneReport {
    private EvalPhoneReport() {
    }

    static void write(JsonNode results, EvalReport report) {
        thesis(results, report);
        JsonNode devices = results.get("devices");
        if (devices.size() == 0) {
            report.paragraph("No phone has been added yet, so these numbers exist for no phone: the time of one frame of"
                    + " each model the app bundles with each skinning method on its CPU (core's scalar kernels, µs,"
                    + " each with its runs' spread), the frames per second that leaves one character at "
                    + EvalReport.num(results, "/displayHz") + " Hz, and the frames per second its GPU draws with "
                    + copies(results) + " copies of the walking character (LBS, DQS and CoR skinned in the vertex"
                    + " shader). Any phone can produce them: the app's Measure, then `skinlab eval --add-device"
                    + " results-android.json` (docs/ar.md, docs/evaluation.md).");
        } else {
            devicesTable(results, report);
        }
        cpuTable(results, report);
        drawnTable(results, report);
        if (results.has("figureSkipped")) {
            report.paragraph("No figure: " + results.get("figureSkipped").asText() + ".");
        } else {
            figure(results, report);
        }
    }

    private static String copies(JsonNode results) {
        JsonNode c = results.get("copies");
        List<String> n = new ArrayList<>();
        for (int i = 0; i < c.size(); i++) {
            n.add(EvalReport.num(results, "/copies/" + i));
        }
        return String.join(", ", n.subList(0, n.size() - 1)) + " and " + n.get(n.size() - 1);
    }

    private static void thesis(JsonNode results, EvalReport report) {
        report.paragraph("The thesis ran its app on a " + results.at("/thesisPhone/device").asText() + ": the "
                + results.at("/thesisPhone/asset").asText() + " (" + EvalReport.num(results, "/thesisPhone/meshes")
                + " mesh) skinned on the CPU and drawn at " + EvalReport.num(results, "/thesisPhone/lbsFps") + " fps with LBS"
                + " and " + EvalReport.num(results, "/thesisPhone/dqsFps") + " with DQS, "
                + EvalReport.num(results, "/thesisPhone/undeformedFps") + " fps without deformation; its desktop drew "
                + copies(results) + " meshes (table below). Those frame rates are its whole app's, drawn; below,"
                + " the CPU's time is one character's frame alone (sample, pose, skin: the time section's protocol),"
                + " and the GPU's frames per second are copies skinned in the vertex shader, the app's default path."
                + " A phone shows at most its display's refresh rate: with vsync every frame rate stops there, so a"
                + " phone at its refresh rate kept up rather than reached its limit.");
    }

    private static void devicesTable(JsonNode results, EvalReport report) {
        report.header("phone", "CPU", "cores", "GPU", "display Hz", "app", "protocol", "added");
        JsonNode devices = results.get("devices");
        for (int d = 0; d < devices.size(); d++) {
            String p = "/devices/" + d + "/results";
            JsonNode r = devices.get(d).get("results");
            JsonNode cpu = r.at("/device/cpu");
            JsonNode gpu = r.get("gpu");
            report.row("`" + EvalPhoneSection.name(r) + "`", cpu.path("name").isTextual() ? "`" + cpu.get("name")
                    .asText() + "`" : "unnamed", EvalReport.num(results, p + "/device/cpu/cores"), gpu.has("renderer")
                    ? "`" + gpu.get("renderer").asText() + "`, `" + gpu.get("version").asText() + "`"
                    : "unknown: `" + gpu.get("unavailable").asText() + "`", EvalReport.num(results,
                    p + "/device/refreshHz"), "`" + r.at("/app/versionName").asText() + "`", r.at("/protocol/name")
                    .asText() + (r.at("/protocol/name").asText().equals("full") ? "" : " (not figures to quote)"),
                    "`" + devices.get(d).get("added").asText() + "`");
        }
        report.line("");
    }

    /** One character on the CPU: a row per model and method, this machine's scalar kernels and each phone's. */
    private static void cpuTable(JsonNode results, EvalReport report) {
        report.heading(3, "One character's frame on the CPU (core's scalar kernels)");
        JsonNode devices = results.get("devices");
        Map<String, String[]> rows = new LinkedHashMap<>();
        int columns = 1 + devices.size();
        // Rows: the phones' models and methods, then this machine's other ones.
        for (int d = 0; d < devices.size(); d++) {
            JsonNode characters = devices.get(d).get("characters");
            int k = 0;
            JsonNode models = devices.get(d).at("/results/models");
            for (int m = 0; m < models.size(); m++) {
                for (int j = 0; j < models.get(m).get("methods").size(); j++, k++) {
                    String p = "/devices/" + d + "/results/models/" + m + "/methods/" + j + "/micros";
                    String c = "/devices/" + d + "/characters/" + k;
                    rows.computeIfAbsent(key(characters.get(k)), x -> new String[columns])[1 + d] =
                            spread(results, p) + " | " + EvalReport.num(results, c + "/fpsAt60Hz") + " ("
                                    + EvalReport.num(results, c + "/framePercent") + " %)";
                }
            }
        }
        JsonNode here = results.path("here");
        for (int i = 0; i < here.size(); i++) {
            if (devices.size() == 0 || rows.containsKey(key(here.get(i)))) {
                rows.computeIfAbsent(key(here.get(i)), x -> new String[columns])[0] = spread(results,
                        "/here/" + i + "/micros") + " | " + EvalReport.num(results, "/here/" + i + "/fpsAt60Hz") + " ("
                        + EvalReport.num(results, "/here/" + i + "/framePercent") + " %)";
            }
        }
        report.paragraph("µs per frame: the median of the runs (their quartiles), and the frames per second that leaves one"
                + " character at " + EvalReport.num(results, "/displayHz") + " Hz (at most that; the share of a "
                + EvalReport.num(results, "/frameMicros") + " µs frame). This machine: the time section's scalar runs,"
                + " for scale" + (results.has("hereMissing") ? " (none: " + results.get("hereMissing").asText() + ")"
                        : "") + (devices.size() == 0 ? "." : "; only the models a phone measured."));
        List<String> header = new ArrayList<>(List.of("model", "method", "this machine µs", "this machine fps"));
        for (int d = 0; d < devices.size(); d++) {
            header.add("`" + label(devices, d) + "` µs");
            header.add("`" + label(devices, d) + "` fps");
        }
        report.header(header.toArray(new String[0]));
        for (Map.Entry<String, String[]> row : rows.entrySet()) {
            List<String> cells = new ArrayList<>(List.of(row.getKey().split("\t")));
            for (String cell : row.getValue()) {
                cells.add(cell == null ? "- | -" : cell);
            }
            report.line("| " + String.join(" | ", cells) + " |");
        }
        report.line("");
    }

    /**
     * How tables and the figure name phone {@code d}: its model, with the app's version where
     * another phone has the same model, and its place where that still does not tell them apart.
     */
    private static String label(JsonNode devices, int d) {
        String model = devices.get(d).at("/results/device/model").asText();
        String version = devices.get(d).at("/results/app/versionName").asText();
        int sameModel = 0;
        int same = 0;
        for (JsonNode other : devices) {
            if (other.at("/results/device/model").asText().equals(model)) {
                sameModel++;
                same += other.at("/results/app/versionName").asText().equals(version) ? 1 : 0;
            }
        }
        return sameModel == 1 ? model : same == 1 ? model + ", app " + version : model + ", app " + version + ", #"
                + (d + 1);
    }

    private static String key(JsonNode row) {
        return "`" + row.get("file").asText() + "`\t" + row.get("method").asText().toUpperCase(Locale.ROOT);
    }

    /** A spread as "median (q1–q3)", or the median alone where only it is kept. */
    private static String spread(JsonNode results, String pointer) {
        JsonNode s = results.at(pointer);
        return EvalReport.num(results, pointer + "/median") + (s.has("q1") ? " (" + EvalReport.num(results,
                pointer + "/q1") + "–" + EvalReport.num(results, pointer + "/q3") + ")" : "");
    }

    /** Frames per second against copies: the thesis' rows, then each phone's GPU per method. */
    private static void drawnTable(JsonNode results, EvalReport report) {
        report.heading(3, "Frames per second against copies");
        JsonNode copies = results.get("copies");
        List<String> header = new ArrayList<>(List.of("who", "skinning", "method"));
        for (int i = 0; i < copies.size(); i++) {
            header.add(EvalReport.num(results, "/copies/" + i) + (i == 0 ? " copy" : " copies"));
        }
        report.paragraph("The thesis' frame rates, then each phone's: the median of its runs (their quartiles), drawn with"
                + " vsync, so at most its display's refresh rate.");
        report.header(header.toArray(new String[0]));
        JsonNode desktop = results.get("thesisDesktop");
        for (String method : new String[] {"dqs", "lbs"}) {
            List<String> row = new ArrayList<>(List.of("thesis' desktop", "CPU", method.toUpperCase(Locale.ROOT)));
            for (int i = 0; i < desktop.size(); i++) {
                row.add(EvalReport.num(results, "/thesisDesktop/" + i + "/" + method + "Fps"));
            }
            report.row(row.toArray(new String[0]));
        }
        for (String method : new String[] {"dqs", "lbs"}) {
            List<String> row = new ArrayList<>(List.of("thesis' " + results.at("/thesisPhone/device").asText(), "CPU",
                    method.toUpperCase(Locale.ROOT), EvalReport.num(results, "/thesisPhone/" + method + "Fps")));
            while (row.size() < header.size()) {
                row.add("-");
            }
            report.row(row.toArray(new String[0]));
        }
        JsonNode devices = results.get("devices");
        for (int d = 0; d < devices.size(); d++) {
            String who = "`" + label(devices, d) + "`";
            String base = "/devices/" + d + "/results/drawn";
            JsonNode drawn = results.at(base);
            if (!drawn.has("points")) {
                List<String> row = new ArrayList<>(List.of(who, "GPU", "not measured: `" + drawn.path("unavailable")
                        .asText() + "`"));
                while (row.size() < header.size()) {
                    row.add("-");
                }
                report.row(row.toArray(new String[0]));
                continue;
            }
            for (String method : methods(drawn)) {
                List<String> row = new ArrayList<>(List.of(who, "GPU", method.toUpperCase(Locale.ROOT)));
                for (int i = 0; i < copies.size(); i++) {
                    int p = point(drawn, copies.get(i).asInt(), method);
                    row.add(p < 0 ? "-" : spread(results, base + "/points/" + p + "/fps"));
                }
                report.row(row.toArray(new String[0]));
            }
        }
        report.line("");
    }

    private static List<String> methods(JsonNode drawn) {
        List<String> methods = new ArrayList<>();
        for (JsonNode p : drawn.get("points")) {
            if (!methods.contains(p.get("method").asText())) {
                methods.add(p.get("method").asText());
            }
        }
        return methods;
    }

    private static int point(JsonNode drawn, int copies, String method) {
        JsonNode points = drawn.get("points");
        for (int i = 0; i < points.size(); i++) {
            if (points.get(i).get("copies").asInt() == copies && points.get(i).get("method").asText().equals(method)) {
                return i;
            }
        }
        return -1;
    }

    /** Each phone's drawn frames per second against copies, a line per method, beside the thesis' points. */
    private static void figure(JsonNode results, EvalReport report) {
        XYChart chart = new XYChartBuilder().width(1150).height(600)
                .title("Frames per second against copies: phones (GPU skinning, vsync) beside the thesis")
                .xAxisTitle("copies").yAxisTitle("frames per second").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setXAxisDecimalPattern("0");
        JsonNode devices = results.get("devices");
        for (int i = 0; i < devices.size(); i++) {
            JsonNode drawn = devices.get(i).at("/results/drawn");
            if (!drawn.has("points")) {
                continue;
            }
            for (String method : methods(drawn)) {
                List<Double> x = new ArrayList<>();
                List<Double> y = new ArrayList<>();
                for (JsonNode p : drawn.get("points")) {
                    if (p.get("method").asText().equals(method)) {
                        x.add(p.get("copies").asDouble());
                        y.add(p.at("/fps/median").asDouble());
                    }
                }
                chart.addSeries(label(devices, i) + " " + method.toUpperCase(Locale.ROOT), x, y);
            }
        }
        List<Double> rates = new ArrayList<>();
        for (JsonNode d : results.get("devices")) {
            double hz = d.at("/results/device/refreshHz").asDouble();
            if (d.at("/results/drawn").has("points") && !rates.contains(hz)) {
                rates.add(hz);
                double last = results.get("copies").get(results.get("copies").size() - 1).asDouble();
                XYSeries cap = chart.addSeries("vsync: at most " + EvalReport.format(d.at("/results/device/refreshHz"))
                        + " fps", List.of(1.0, last), List.of(hz, hz));
                cap.setMarker(SeriesMarkers.NONE);
                cap.setLineStyle(SeriesLines.DASH_DASH);
                cap.setLineColor(java.awt.Color.GRAY);
            }
        }
        for (String method : new String[] {"dqs", "lbs"}) {
            XYSeries s = chart.addSeries("thesis' phone " + method.toUpperCase(Locale.ROOT) + " (CPU skinning)", List.of(results.at("/thesisPhone/meshes")
                    .asDouble()), List.of(results.at("/thesisPhone/" + method + "Fps").asDouble()));
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(method.equals("dqs") ? SeriesMarkers.TRIANGLE_DOWN : SeriesMarkers.TRIANGLE_UP);
            s.setMarkerColor(java.awt.Color.BLACK);
        }
        for (String method : new String[] {"dqs", "lbs"}) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (JsonNode t : results.get("thesisDesktop")) {
                x.add(t.get("meshes").asDouble());
                y.add(t.get(method + "Fps").asDouble());
            }
            XYSeries s = chart.addSeries("thesis' desktop " + method.toUpperCase(Locale.ROOT) + " (CPU skinning)", x, y);
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(method.equals("dqs") ? SeriesMarkers.DIAMOND : SeriesMarkers.SQUARE);
        }
        report.figure("phone-drawn.png", "Phones' frames per second against copies beside the thesis", chart);
    }
}
