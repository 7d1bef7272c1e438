package org.skinlab.android;

import java.util.ArrayList;
import java.util.List;

import android.content.Context;
import android.graphics.Color;
import android.view.Gravity;
import android.view.View;
import android.view.WindowInsets;
import android.widget.Button;
import android.widget.FrameLayout;
import android.widget.HorizontalScrollView;
import android.widget.LinearLayout;
import android.widget.TextView;

import org.skinlab.android.logic.AppActions;
import org.skinlab.android.logic.PermissionFlow;

/**
 * The views over the camera picture: the status line at the top, a button per user function at
 * the bottom ({@link AppActions}, labelled by the action's current state, greyed out while it
 * cannot act), and the camera
 * permission's explanation with its retry button over everything; the status line and the
 * buttons kept clear of the system bars. UI thread only.
 */
final class ArControls {
    /** The picture under the controls and the controls: the Activity's content view. */
    final FrameLayout root;
    private final TextView status;
    private final HorizontalScrollView buttonRow;
    private final List<AppActions.Action> actions;
    private final List<Button> buttons = new ArrayList<>();
    private final LinearLayout explanation;
    private final TextView explanationText;
    private final Button retry;

    ArControls(Context context, View picture, List<AppActions.Action> actions, Runnable onRetry) {
        this.actions = actions;
        root = new FrameLayout(context);
        root.addView(picture);

        status = new TextView(context);
        status.setTextColor(Color.WHITE);
        status.setBackgroundColor(0x88000000);
        root.addView(status, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.WRAP_CONTENT, Gravity.TOP));

        LinearLayout row = new LinearLayout(context);
        row.setOrientation(LinearLayout.HORIZONTAL);
        for (AppActions.Action a : actions) {
            Button b = new Button(context);
            b.setAllCaps(false);
            b.setText(a.label().get());
            b.setEnabled(a.enabled().getAsBoolean());
            b.setOnClickListener(v -> {
                a.run().run();
                b.setText(a.label().get());
            });
            buttons.add(b);
            row.addView(b);
        }
        buttonRow = new HorizontalScrollView(context);
        buttonRow.setBackgroundColor(0x66000000);
        buttonRow.addView(row);
        root.addView(buttonRow, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.WRAP_CONTENT, Gravity.BOTTOM));

        explanation = new LinearLayout(context);
        explanation.setOrientation(LinearLayout.VERTICAL);
        explanation.setGravity(Gravity.CENTER);
        explanation.setBackgroundColor(0xEE202024);
        explanation.setPadding(48, 48, 48, 48);
        explanationText = new TextView(context);
        explanationText.setTextColor(Color.WHITE);
        explanation.addView(explanationText);
        retry = new Button(context);
        retry.setText("Allow the camera");
        retry.setOnClickListener(v -> onRetry.run());
        explanation.addView(retry);
        root.addView(explanation, new FrameLayout.LayoutParams(FrameLayout.LayoutParams.MATCH_PARENT,
                FrameLayout.LayoutParams.MATCH_PARENT));
        // From target SDK 35 on, the window reaches under the system bars and the display cutout:
        // the camera image may, the status line and the buttons keep clear of them.
        root.setOnApplyWindowInsetsListener((v, insets) -> {
            padInsets(status, insets, true);
            padInsets(buttonRow, insets, false);
            return insets;
        });
    }

    /** The status line's text, and each button's label and whether it can be tapped, as its action now reads. */
    void refresh(CharSequence statusLine) {
        status.setText(statusLine);
        for (int i = 0; i < buttons.size(); i++) {
            buttons.get(i).setText(actions.get(i).label().get());
            buttons.get(i).setEnabled(actions.get(i).enabled().getAsBoolean());
        }
    }

    /** The permission flow's screen: the explanation (with retry, or pointing to the settings) or none. */
    void show(PermissionFlow.Screen screen) {
        boolean explain = screen == PermissionFlow.Screen.EXPLAIN_AND_RETRY
                || screen == PermissionFlow.Screen.EXPLAIN_SETTINGS;
        explanation.setVisibility(explain ? View.VISIBLE : View.GONE);
        retry.setVisibility(screen == PermissionFlow.Screen.EXPLAIN_AND_RETRY ? View.VISIBLE : View.GONE);
        explanationText.setText(screen == PermissionFlow.Screen.EXPLAIN_SETTINGS
                ? PermissionFlow.EXPLANATION + "\n\nAllow the camera for skinlab AR in Android's settings (Apps, "
                        + "skinlab AR, Permissions), then come back."
                : PermissionFlow.EXPLANATION);
    }

    @SuppressWarnings("deprecation") // getSystemWindowInset*: their successors need API 30 (min is 26)
    private static void padInsets(View v, WindowInsets insets, boolean top) {
        v.setPadding(16 + insets.getSystemWindowInsetLeft(), top ? 8 + insets.getSystemWindowInsetTop() : 0,
                16 + insets.getSystemWindowInsetRight(), top ? 8 : insets.getSystemWindowInsetBottom());
    }
}
