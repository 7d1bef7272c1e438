/**
 * {@code skinlab eval}'s report: {@link org.skinlab.desktop.eval.Evaluation} runs the sections
 * ({@code EvalSection}: load, time, phone, crowds, quality, pictures, tracking, advice), each measuring
 * into results.json and writing its part of README.md and its figures from those results alone
 * (docs/evaluation.md); {@code EvalDeviceFiles} adds a phone's device file to a report's results; {@code InfluenceCapReport}, the error of capping influences, is shared with
 * {@code skinlab inspect}. It measures with {@link org.skinlab.desktop.bench}, loads through the
 * root package's {@code ModelFiles}, draws crowds with {@link org.skinlab.desktop.render} and the
 * pictures by {@code skinlab view} in a child JVM, and uses core; the command line
 * ({@link org.skinlab.desktop.cli}) calls it, never the other way round.
 */
package org.skinlab.desktop.eval;
