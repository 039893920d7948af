#version 330 core
// SPDX-License-Identifier: MIT
// One camera-facing triangle per ball (instanced, one draw call for all balls); ball.frag
// ray-casts the sphere inside it. A ball is never drawn smaller than minPixels on screen.
layout(location = 0) in vec2 corner; // of the triangle around the unit circle
layout(location = 1) in vec3 centre; // per ball, world
layout(location = 2) in vec4 colour; // per ball
layout(location = 3) in vec4 turn;   // per ball where the balls turn: orientation quaternion (x, y, z, w)

uniform mat4 view;
uniform mat4 projection;
uniform float radius;        // world units
uniform float minPixels;     // smallest drawn radius, in pixels
uniform float pixelsPerUnit; // pixels per world unit at unit distance
uniform int selected;        // index of the selected ball, -1 for none
uniform int pattern;         // 1: the balls turn, each carries the beach-ball pattern turned by `turn`
uniform float hideBeyondX;   // a ball whose centre is beyond this x has left the scene: not drawn

out vec3 rayPoint;           // view-space point on the triangle
flat out vec3 sphereCentre;  // view space
flat out float sphereRadius;
flat out float ringRadius;   // the selection ring's outer radius (= sphereRadius when not selected)
flat out vec4 ballColour;
flat out mat3 viewToBody;    // carries a view-space direction into the ball's own frame (pattern only)
flat out float ballPixels;   // the ball's radius on screen, pixels (pattern only)

// The rotation matrix of unit quaternion q = (x, y, z, w), transposed: R(q) carries the
// ball's frame to the world (x_world = q x_body q*), and for a rotation the transpose is
// the inverse. R(q) = I + 2 w [v]x + 2 [v]x^2 with v = (x, y, z), written out entry by
// entry; mat3() takes columns, so R's rows are given as the columns.
mat3 worldToBody(vec4 q)
{
    float x = q.x, y = q.y, z = q.z, w = q.w;
    return mat3(vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)),
                vec3(2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)),
                vec3(2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)));
}

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
    if (pattern == 1) {
        // The view matrix is a rigid motion: its rotation part, transposed, carries view
        // directions back to the world; worldToBody then into the ball.
        viewToBody = worldToBody(turn) * transpose(mat3(view));
        ballPixels = r * pixelsPerUnit / depth;
    } else {
        viewToBody = mat3(1.0);
        ballPixels = 0.0;
    }
    float dist = length(c);
    if (dist <= outer * 1.001 || c.z >= 0.0 || centre.x > hideBeyondX) {
        // The eye is inside the ball, it is behind the eye, or it has left the scene: nothing to draw.
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
