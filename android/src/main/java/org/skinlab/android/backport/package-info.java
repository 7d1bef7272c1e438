/**
 * Stand-ins for the few Java methods that libraries call but Android 8 lacks
 * ({@code Math.fma}, {@code ByteArrayOutputStream.toString(Charset)}): R8 rewrites those calls in
 * the APK to these classes (android/backports.json), which compute the same results with API 26
 * alone. Depends on nothing of ours.
 */
package org.skinlab.android.backport;
