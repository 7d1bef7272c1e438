package org.skinlab.android;

import android.content.Context;
import android.content.pm.PackageManager;

import org.robolectric.annotation.Implementation;
import org.robolectric.annotation.Implements;
import org.robolectric.annotation.RealObject;
import org.robolectric.shadows.ShadowContextImpl;

/**
 * Android 17 asks a context for a permission's "request state" before it shows the permission
 * dialog, and answers at once, without a dialog, when the permission is already granted.
 * Robolectric 4.17 answers "granted" for every permission there, whatever the test granted or
 * denied, so at API 37 no dialog would ever open. This makes the request state follow the
 * permissions the test grants and denies, as the platform's does: granted, or requestable. It
 * extends Robolectric's own shadow of the class, which keeps everything else (a class has one
 * shadow); below API 37 the method is never called.
 */
@Implements(className = "android.app.ContextImpl", isInAndroidSdk = false)
public class ShadowPermissionRequestState extends ShadowContextImpl {
    /** Context.PERMISSION_REQUEST_STATE_GRANTED and _REQUESTABLE (API 37; the tests compile against 34). */
    private static final int GRANTED = 0;
    private static final int REQUESTABLE = 1;

    @RealObject
    private Context context;

    @Implementation(minSdk = 37)
    protected int getPermissionRequestState(String permission) {
        return context.checkSelfPermission(permission) == PackageManager.PERMISSION_GRANTED ? GRANTED : REQUESTABLE;
    }
}
