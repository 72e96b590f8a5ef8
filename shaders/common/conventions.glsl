// OpenWorld conventions, written once (docs/design.md, "Conventions"):
//   units     metres, seconds, radians in GLSL (degrees only at the user interface)
//   axes      Y up, X east, Z south (north is -Z), right-handed
//   spaces    suffixes name the space: wsPos world, vsPos view, lsPos light, csPos clip, tsNormal tangent
//   colour    linear RGB everywhere; the scene target stores sRGB-encoded output (common/color.glsl)
const float PI = 3.14159265358979;
