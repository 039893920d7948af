#version 330 core
// SPDX-License-Identifier: MIT
// Ray-cast sphere impostor: the ray from the eye through this fragment meets the sphere
// or the fragment is discarded; the hit point's depth is written, so balls intersect
// each other and the scene correctly. Lambert plus Blinn-Phong lighting.
in vec3 rayPoint;
flat in vec3 sphereCentre;
flat in float sphereRadius;
flat in float ringRadius;
flat in vec4 ballColour;

uniform mat4 projection;
uniform vec3 lightDir; // view space, unit, towards the light

out vec4 fragColour;

float depthOf(vec3 p)
{
    vec4 clip = projection * vec4(p, 1.0);
    return 0.5 * (clip.z / clip.w) + 0.5;
}

void main()
{
    vec3 d = normalize(rayPoint);
    float b = dot(d, sphereCentre);                          // along the ray to the closest approach
    float miss2 = dot(sphereCentre, sphereCentre) - b * b;   // squared distance of the ray from the centre
    float r2 = sphereRadius * sphereRadius;
    if (miss2 > r2) {
        if (miss2 > ringRadius * ringRadius)
            discard;
        fragColour = vec4(1.0, 0.80, 0.05, 1.0); // the selection ring, just in front of the ball
        gl_FragDepth = depthOf(d * (b - sphereRadius));
        return;
    }
    vec3 hit = d * (b - sqrt(r2 - miss2));
    vec3 n = (hit - sphereCentre) / sphereRadius;
    float diffuse = max(dot(n, lightDir), 0.0);
    float specular = pow(max(dot(n, normalize(lightDir - d)), 0.0), 48.0);
    fragColour = vec4(ballColour.rgb * (0.42 + 0.68 * diffuse) + vec3(0.35 * specular), 1.0);
    gl_FragDepth = depthOf(hit);
}
