#version 330 core
// SPDX-License-Identifier: MIT
// Ray-cast sphere impostor: the ray from the eye through this fragment meets the sphere
// or the fragment is discarded; the hit point's depth is written, so balls intersect
// each other and the scene correctly. Lambert plus Blinn-Phong lighting. Kept cheap:
// writing the depth turns off early depth rejection, so every covered fragment of every
// ball runs this, thousands of balls deep under software OpenGL.
in vec3 rayPoint;
flat in vec3 sphereCentre;
flat in float sphereRadius;
flat in float ringRadius;
flat in vec4 ballColour;
flat in mat3 viewToBody;
flat in float ballPixels;

uniform vec2 depthTerms; // projection (2,2) and (2,3): clip z = a z + b, clip w = -z
uniform vec3 lightDir;   // view space, unit, towards the light
uniform int ghost;       // 1: a comparison run's ball, pale, see-through, outlined
uniform int pattern;     // 1: the balls turn and carry the beach-ball pattern

out vec4 fragColour;

float depthOf(float z)
{
    return 0.5 * (depthTerms.x * z + depthTerms.y) / -z + 0.5;
}

// The beach-ball pattern at body-frame normal b (unit): six gores about the ball's pole
// (its own z axis), alternately the ball's colour and a white tinted by it, a dark cap on
// the +z pole and a white one on the -z pole, so a turn about any axis shows. With
// b = (rho cos phi, rho sin phi, z), the gores are the signs of
//     sin(3 phi) = (3 x^2 y - y^3) / rho^3      (the imaginary part of (x + i y)^3),
// no angle needed; the edges are smoothed over one pixel (fwidth). On a ball a few
// pixels wide the pattern would only flicker: it fades out below 7 pixels of radius.
vec3 beachBall(vec3 b, vec3 colour)
{
    float rho2 = max(b.x * b.x + b.y * b.y, 1e-8);
    float gores = (3.0 * b.x * b.x * b.y - b.y * b.y * b.y) / (rho2 * sqrt(rho2));
    float soft = fwidth(gores) + 1e-4;
    float white = smoothstep(-soft, soft, gores);
    vec3 paint = mix(colour, mix(colour, vec3(1.0), 0.85), white);
    float capSoft = fwidth(b.z) + 1e-4;
    paint = mix(paint, mix(colour, vec3(1.0), 0.85), smoothstep(0.9 - capSoft, 0.9 + capSoft, -b.z));
    paint = mix(paint, 0.22 * colour, smoothstep(0.9 - capSoft, 0.9 + capSoft, b.z));
    return mix(colour, paint, smoothstep(3.0, 7.0, ballPixels));
}

void main()
{
    vec3 d = normalize(rayPoint);
    float b = dot(d, sphereCentre);                        // along the ray to the closest approach
    float miss2 = dot(sphereCentre, sphereCentre) - b * b; // squared distance of the ray from the centre
    float r2 = sphereRadius * sphereRadius;
    if (miss2 > r2) {
        if (miss2 > ringRadius * ringRadius)
            discard;
        fragColour = vec4(1.0, 0.80, 0.05, 1.0); // the selection ring, just in front of the ball
        gl_FragDepth = depthOf(d.z * (b - sphereRadius));
        return;
    }
    vec3 hit = d * (b - sqrt(r2 - miss2));
    vec3 n = (hit - sphereCentre) / sphereRadius;
    float diffuse = max(dot(n, lightDir), 0.0);
    float s = max(dot(n, normalize(lightDir - d)), 0.0);
    s *= s; // s^48 by squaring: s^2, s^4, s^8, s^16, then s^16 s^32
    s *= s;
    s *= s;
    s *= s;
    float specular = s * s * s;
    vec3 albedo = pattern == 1 ? beachBall(viewToBody * n, ballColour.rgb) : ballColour.rgb;
    vec3 lit = albedo * (0.42 + 0.68 * diffuse) + vec3(0.35 * specular);
    if (ghost == 1) {
        // Tinted towards the charts' comparison violet, washed towards white and
        // see-through, with a dark outline (the ghost is drawn a little larger than the
        // ball, so one that agrees with the run shows as a violet ring around it): |n.d|
        // is the cosine between the normal and the ray, 1 at the centre of the disc and 0
        // at its edge, so rim = 1 - |n.d| grows from 0 to 1 towards the outline.
        float rim = 1.0 - abs(dot(n, d));
        float edge = smoothstep(0.55, 0.8, rim);
        vec3 hue = mix(ballColour.rgb, vec3(0.42, 0.12, 0.72), 0.7);
        vec3 tinted = hue * (0.42 + 0.68 * diffuse) + vec3(0.35 * specular);
        vec3 pale = mix(tinted, vec3(1.0), 0.45);
        fragColour = vec4(mix(pale, 0.45 * hue, edge), mix(0.45, 0.95, edge));
    } else {
        fragColour = vec4(lit, 1.0);
    }
    gl_FragDepth = depthOf(hit.z);
}
