/**
 * Writing output so that nothing is lost: {@link org.openworld.engine.files.AtomicFiles} writes a file, or a whole
 * folder of files, beside its place and renames it into place, so a reader (or a crash) sees the old output or the
 * new one, never a part of one or a mix of both.
 */
package org.openworld.engine.files;
