#version 330 core
// SPDX-License-Identifier: MIT
// A soft dark disc on the floor under each ball (instanced): strong when the ball is
// close to the floor, fading with height, so contact reads at a glance.
layout(location = 0) in vec2 corner; // of the triangle around the unit circle
layout(location = 1) in vec3 centre;

uniform mat4 view;
uniform mat4 projection;
uniform float radius;
uniform float minPixels;
uniform float pixelsPerUnit;
uniform float floorY;
uniform float fadeHeight; // height above the floor where the cue has faded out
uniform float hideBeyondX; // a ball beyond this x has left the scene: no cue

out vec2 local;
flat out float strength;

void main()
{
    vec3 below = vec3(centre.x, floorY, centre.z);
    float depth = max(-(view * vec4(below, 1.0)).z, 1e-6);
    float r = max(radius, minPixels * depth / pixelsPerUnit);
    float h = max(centre.y - floorY, 0.0);
    strength = 0.55 * clamp(1.0 - h / fadeHeight, 0.0, 1.0);
    local = corner;
    if (strength <= 0.0 || centre.x > hideBeyondX) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    float s = r * (1.15 + 1.2 * h / fadeHeight);
    gl_Position = projection * view * vec4(below + vec3(corner.x * s, 0.0, corner.y * s), 1.0);
}
