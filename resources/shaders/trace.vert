#version 330 core
// SPDX-License-Identifier: MIT
// The selected ball's path as a band `width` pixels wide (core-profile lines are one pixel,
// lost on a projector and on the street's asphalt). Each segment is a quad of four corners:
// a corner lies at `position`, the segment's other end is `other`, and `side` (+1 or -1)
// says which edge of the band it is on. Both ends are projected; the corner moves `width`/2
// pixels across the segment's direction on screen and `width`/2 back along it, so the
// bands of neighbouring segments overlap at a bend instead of leaving a notch.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 other;
layout(location = 2) in float side;
uniform mat4 viewProjection;
uniform vec2 viewport; // pixels
uniform float width;   // pixels
uniform vec4 colour;
out vec4 vertexColour;

void main()
{
    vertexColour = colour;
    vec4 here = viewProjection * vec4(position, 1.0);
    vec4 there = viewProjection * vec4(other, 1.0);
    // A segment with an end at or behind the eye has no direction on screen: it is left out
    // (all four corners of its quad land outside the clip volume).
    if (here.w <= 1e-6 || there.w <= 1e-6) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 a = here.xy / here.w * 0.5 * viewport; // pixels from the view's centre
    vec2 b = there.xy / there.w * 0.5 * viewport;
    vec2 along = b - a;
    float length = max(sqrt(dot(along, along)), 1e-6);
    along /= length;
    vec2 across = vec2(-along.y, along.x);
    vec2 offset = (side * across - along) * 0.5 * width; // pixels
    // Back to clip space: x_ndc = 2 x_px / viewport, times w.
    gl_Position = here + vec4(offset / (0.5 * viewport) * here.w, 0.0, 0.0);
}
