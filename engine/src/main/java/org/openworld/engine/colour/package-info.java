/**
 * Colour science for comparing pictures, without OpenGL: {@link org.openworld.engine.colour.Lab} turns an 8-bit sRGB
 * colour into CIELAB (D65), where distance follows what people see; {@link org.openworld.engine.colour.DeltaE} is
 * CIEDE2000, the CIE's colour difference formula; {@link org.openworld.engine.colour.ImageComparison} applies it to
 * two pictures pixel by pixel and draws a difference image. {@code openworld diff} prints what it finds.
 * {@link org.openworld.engine.colour.Repetition} measures how much one picture repeats itself (the peak of its
 * luminance's autocorrelation away from zero shift): how visibly a texture tiles.
 * {@link org.openworld.engine.colour.Shimmer} counts the pixels that change between two frames noticeably more than
 * in supersampled references of them: aliasing in motion, with the motion itself taken out.
 *
 * <p>Why not compare the RGB numbers? Equal steps in sRGB are not equal steps to the eye: a change of 10 in a dark
 * blue is far easier to miss than the same change in a mid green. CIELAB was built so that distances are roughly
 * perceptual, and CIEDE2000 corrects its known faults (blues, greys, saturated colours). Sharma, Wu and Dalal, "The
 * CIEDE2000 colour-difference formula: implementation notes, supplementary test data, and mathematical
 * observations", Color Research and Application 30(1), 2005, give the formula step by step and the test pairs the
 * unit tests check.
 *
 * <p>Limits: the formula compares two flat colours side by side; in a textured picture a difference must be larger
 * to be seen, and neither blur nor displacement is measured (a picture moved by one pixel differs everywhere).
 */
package org.openworld.engine.colour;
