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

uniform vec2 depthTerms; // projection (2,2) and (2,3): clip z = a z + b, clip w = -z
uniform vec3 lightDir;   // view space, unit, towards the light

out vec4 fragColour;

float depthOf(float z)
{
    return 0.5 * (depthTerms.x * z + depthTerms.y) / -z + 0.5;
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
    fragColour = vec4(ballColour.rgb * (0.42 + 0.68 * diffuse) + vec3(0.35 * specular), 1.0);
    gl_FragDepth = depthOf(hit.z);
}
