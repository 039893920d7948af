#version 330 core
// SPDX-License-Identifier: MIT
in vec2 local;
flat in float strength;
out vec4 fragColour;

void main()
{
    float a = strength * (1.0 - smoothstep(0.25, 1.0, length(local)));
    if (a <= 0.004)
        discard;
    fragColour = vec4(0.05, 0.07, 0.12, a);
}
