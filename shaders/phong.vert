// Per-fragment Phong: the vertex stage only passes the eye-space position and
// normal on, so the fragment stage can evaluate the fixed-function lighting
// equation at every pixel (see phong.frag and core/lighting.h).
#version 120

varying vec3 wbEyePos;    // eye-space position of the fragment
varying vec3 wbEyeNormal; // eye-space normal, interpolated (re-normalised per fragment)

void main() {
    wbEyePos = vec3(gl_ModelViewMatrix * gl_Vertex);
    wbEyeNormal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_TexCoord[0] = gl_MultiTexCoord0;
}
