/**
 * Real elevation models at true scale: GeoTIFF, 16-bit PNG and raw float32 of any size, their metres kept, placed in
 * the terrain's tile, with the octaves below the data's resolution synthesised. The page {@code docs/real-places.md}
 * shows a real place.
 *
 * <p><b>Data path.</b> {@code terrain.import-file} → {@link org.openworld.engine.elevation.ElevationImport}: a
 * {@code .tif/.tiff} goes to {@link org.openworld.engine.elevation.GeoTiff}, a PNG or raw file with a JSON sidecar to
 * {@link org.openworld.engine.elevation.Sidecar}; both give an {@link org.openworld.engine.elevation.ElevationGrid}
 * (w × h heights in metres, two spacings), whose no-data holes are filled from their rims; then
 * {@link org.openworld.engine.elevation.TileEmbedding} resamples it (Catmull-Rom) into a 2^n tile at one spacing,
 * centred on the origin, fades its surroundings into a plain, subtracts {@code terrain.sea-level} and adds
 * {@link org.openworld.engine.elevation.DetailBands}. The tile is an ordinary
 * {@link org.openworld.engine.terrain.HeightMap}: the pyramid, LOD, materials, snow, water (at height 0) and shadows
 * work on it unchanged; the snow map and the materials read it by altitude in metres, normalised height
 * n = (h + seaLevel) / 5000 m ({@link org.openworld.engine.elevation.ElevationImport#trueScale}), so the fractions
 * {@code terrain.snow-base} and {@code snow-full} put snow from 1750 m and closed fields from 3000 m. Files this package does not take (a PNG or raw
 * file without a sidecar) go to {@link org.openworld.engine.terrain.HeightImport}, square and normalised.
 *
 * <p><b>Detail: formula.</b> The model's power spectrum is fitted as P(f) = 10^c f^s over its trusted octaves; the
 * missing octaves, down to the tile's spacing d, are the unbounded world's octave bands
 * ({@link org.openworld.engine.terrain.BandedHeights}) with β = −s/2 and standard deviation σ from Parseval,
 * σ² = 2π E²/n⁴ · 10^c (f₂^(s+2) − f₁^(s+2))/(s+2) between the model's Nyquist frequency f₁ = 1/(2D) and
 * f₂ = 1/(2d). The large shapes stay the data's: the bands hold only wavelengths shorter than 2D.
 *
 * <p><b>Why TwelveMonkeys for TIFF.</b> Its TIFF reader (Maven Central, com.twelvemonkeys.imageio:imageio-tiff
 * 3.14.0, a maintained release line since 2009) reads float32, float64, int16, uint16 and int32 samples, strips or
 * tiles, the compressions GDAL writes (Deflate, LZW, PackBits) and BigTIFF, and hands every tag, GeoTIFF's included,
 * through {@code TIFFImageMetadata.getTIFFField}; it is an ImageIO plugin, so nothing else in the engine changes. Apache
 * Commons Imaging reads the same samples and tags, but has only had 1.0 alpha releases, with API changes between
 * them. The JDK's own TIFF plugin reads no BigTIFF. TwelveMonkeys' writer has no float32 samples; the tests write
 * those with the JDK's writer.
 *
 * <p><b>Cost.</b> Reading: 8 bytes a model sample while decoding; the tile: 16 bytes a sample (heights, pyramid, snow
 * and sky maps, working copies), checked against the free heap before anything is allocated, so a model too large
 * fails with one line and the estimate. Time: a Catmull-Rom (16 samples) plus 16 samples per synthesised octave for
 * each tile sample.
 *
 * <p><b>Limits.</b> The map is drawn flat: a geographic model's degrees become metres at its centre's latitude (1.3 %
 * off at the edges of a 1°-tall map at 36° N); rotated or sheared models (ModelTransformation) are refused by
 * their missing pixel scale; the tile holds at most 8192 samples a side; the detail is statistically the model's,
 * not eroded: its valleys do not join the data's drainage.
 */
package org.openworld.engine.elevation;
