/**
 * The desktop's side of augmented reality: camera frames and intrinsics from files, the
 * {@code skinlab track} output. The tracking itself is core's {@code org.skinlab.ar}.
 */
package org.skinlab.desktop.ar;
