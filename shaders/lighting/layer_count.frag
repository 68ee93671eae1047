#version 450 core
// One BLEND layer at this pixel, added to the transparency debug view's count (TransparencyDebugPass).
layout(location = 0) out vec4 outCount;

void main() { outCount = vec4(1.0); }
