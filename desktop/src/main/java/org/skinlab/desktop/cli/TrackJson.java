package org.skinlab.desktop.cli;

import java.util.List;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.MarkerDetection;

/**
 * One frame of {@code skinlab track}'s JSON (docs/ar.md): {@code {"frame", "millis", "detections":
 * [{"id", "corners": [[x,y] x4], "R": [[3x3]], "t": [x,y,z]}]}}. {@code ar-demo}'s true poses are
 * written with it too, so that the two files compare entry by entry.
 */
final class TrackJson {
    private TrackJson() {
    }

    /** Adds a frame to {@code frames}; {@code millis} NaN leaves the time out (a ground truth takes none). */
    static void addFrame(ArrayNode frames, String name, double millis, List<MarkerDetection> found) {
        ObjectNode frame = frames.addObject();
        frame.put("frame", name);
        if (!Double.isNaN(millis)) {
            frame.put("millis", Math.round(millis * 1000) / 1000.0);
        }
        ArrayNode detections = frame.putArray("detections");
        for (MarkerDetection d : found) {
            ObjectNode o = detections.addObject();
            o.put("id", d.id());
            ArrayNode corners = o.putArray("corners");
            for (int i = 0; i < 4; i++) {
                corners.addArray().add(d.cornerX(i)).add(d.cornerY(i));
            }
            ArrayNode r = o.putArray("R");
            double[] rot = d.rotation();
            for (int row = 0; row < 3; row++) {
                r.addArray().add(rot[3 * row]).add(rot[3 * row + 1]).add(rot[3 * row + 2]);
            }
            double[] t = d.translation();
            o.putArray("t").add(t[0]).add(t[1]).add(t[2]);
        }
    }
}
