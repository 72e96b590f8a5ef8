#version 330 core
// The terrain in the sun's shadow pass: depth only (the rasteriser writes it), no colour, no material.
void main() {
}
