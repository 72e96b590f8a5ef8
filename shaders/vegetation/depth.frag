#version 330 core
// The trees in the sun's shadow pass: depth only (the rasteriser writes it), no colour.
void main() {
}
