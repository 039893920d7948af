#version 330 core
// SPDX-License-Identifier: MIT
in vec4 vertexColour;
out vec4 fragColour;

void main()
{
    fragColour = vertexColour;
}
