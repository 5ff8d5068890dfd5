#version 120
// Blinn bump mapping (section 1.5.2), vertex stage: passes the surface frame to the
// fragment stage in eye space. Attributes: texture unit 0 = (s, t); unit 1 = the unit
// tangent ∂p/∂s/|∂p/∂s|; unit 2 = (|∂p/∂s|, |∂p/∂t|), the lengths of the partial derivatives.
varying vec3 vPos;     // eye-space position
varying vec3 vNormal;  // eye-space normal n of the smooth surface
varying vec3 vTangent; // eye-space unit tangent along s
varying vec2 vScale;   // |p_s|, |p_t| (object units per unit of s and t)
varying vec2 vTex;     // (s, t)

void main() {
    vPos = vec3(gl_ModelViewMatrix * gl_Vertex);
    vNormal = gl_NormalMatrix * gl_Normal;
    vTangent = mat3(gl_ModelViewMatrix) * gl_MultiTexCoord1.xyz; // a direction in the surface
    vScale = gl_MultiTexCoord2.xy;
    vTex = gl_MultiTexCoord0.xy;
    gl_Position = ftransform();
}
