/**
 * The COLLADA importer: {@link org.skinlab.collada.ColladaImporter} reads a file into an immutable
 * {@link org.skinlab.model.Model}, one loader per COLLADA library, through an XML reader that
 * refuses DTDs and entities. Problems that make a file unusable are
 * {@link org.skinlab.collada.ColladaException}s naming the file and the element; what is
 * tolerated becomes a warning in the model. Offline work: runs once per file, never per frame.
 * See docs/importer.md for the mapping and the leniency decisions.
 * Depends on {@code org.skinlab.model}, JOML and the JDK's SAX parser only.
 */
package org.skinlab.collada;
