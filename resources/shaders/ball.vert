#version 330 core
// SPDX-License-Identifier: MIT
// One camera-facing triangle per ball (instanced, one draw call for all balls); ball.frag
// ray-casts the sphere inside it. A ball is never drawn smaller than minPixels on screen.
layout(location = 0) in vec2 corner; // of the triangle around the unit circle
layout(location = 1) in vec3 centre; // per ball, world
layout(location = 2) in vec4 colour; // per ball

uniform mat4 view;
uniform mat4 projection;
uniform float radius;        // world units
uniform float minPixels;     // smallest drawn radius, in pixels
uniform float pixelsPerUnit; // pixels per world unit at unit distance
uniform int selected;        // index of the selected ball, -1 for none

out vec3 rayPoint;           // view-space point on the triangle
flat out vec3 sphereCentre;  // view space
flat out float sphereRadius;
flat out float ringRadius;   // the selection ring's outer radius (= sphereRadius when not selected)
flat out vec4 ballColour;

void main()
{
    vec3 c = (view * vec4(centre, 1.0)).xyz;
    float depth = max(-c.z, 1e-6);
    float r = max(radius, minPixels * depth / pixelsPerUnit);
    float outer = r;
    if (gl_InstanceID == selected)
        outer = max(1.35 * r, r + 3.0 * depth / pixelsPerUnit);
    sphereCentre = c;
    sphereRadius = r;
    ringRadius = outer;
    ballColour = colour;
    float dist = length(c);
    if (dist <= outer * 1.001 || c.z >= 0.0) {
        // The eye is inside the ball or it is behind the eye: nothing to draw.
        rayPoint = vec3(0.0);
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    // Seen from distance d, a sphere of radius R has, in the plane through its centre
    // facing the eye, an outline of radius R d / sqrt(d^2 - R^2): the triangle around a
    // circle of that radius covers it.
    float outline = outer * dist / sqrt(dist * dist - outer * outer);
    vec3 forward = c / dist;
    vec3 side = abs(forward.y) < 0.99 ? cross(forward, vec3(0.0, 1.0, 0.0)) : cross(forward, vec3(1.0, 0.0, 0.0));
    vec3 right = normalize(side);
    vec3 up = cross(right, forward);
    rayPoint = c + (corner.x * right + corner.y * up) * outline;
    gl_Position = projection * vec4(rayPoint, 1.0);
}
