// The OpenGL 2.1 fixed-function lighting equation (spec §2.14.1, core/lighting.h)
// evaluated per fragment from the fixed-function state (gl_LightSource,
// gl_FrontMaterial, gl_LightModel), so with the same glLight/glMaterial calls it
// gives what the fixed pipeline computes per vertex, but at every pixel.
// GLSL 1.20 has no built-in for GL_LIGHT_MODEL_LOCAL_VIEWER or for which lights
// are enabled, hence the two uniforms.
#version 120

uniform int wbLightCount;    // lights 0..wbLightCount-1 are used (0..8)
uniform bool wbLocalViewer;  // GL_LIGHT_MODEL_LOCAL_VIEWER

varying vec3 wbEyePos;
varying vec3 wbEyeNormal;

void main() {
    vec3 n = normalize(wbEyeNormal);
    if (!gl_FrontFacing) n = -n; // back faces lit from their own side (two-sided)
    vec3 toEye = wbLocalViewer ? normalize(-wbEyePos) : vec3(0.0, 0.0, 1.0);
    vec3 c = gl_FrontLightModelProduct.sceneColor.rgb; // e_cm + a_cm * a_cs
    for (int i = 0; i < 8; ++i) {
        if (i >= wbLightCount) break;
        vec4 p = gl_LightSource[i].position;
        vec3 vp;
        float att = 1.0;
        float spot = 1.0;
        if (p.w != 0.0) {
            vec3 d = p.xyz / p.w - wbEyePos;
            float dist = length(d);
            vp = d / max(dist, 1e-20);
            att = 1.0 / max(gl_LightSource[i].constantAttenuation +
                                gl_LightSource[i].linearAttenuation * dist +
                                gl_LightSource[i].quadraticAttenuation * dist * dist,
                            1e-12);
            if (gl_LightSource[i].spotCutoff != 180.0) {
                float cosAngle = max(dot(-vp, normalize(gl_LightSource[i].spotDirection)), 0.0);
                // pow(0, 0) is undefined in GLSL: exponent 0 means a hard-edged cone of 1.
                float e = gl_LightSource[i].spotExponent;
                spot = cosAngle >= gl_LightSource[i].spotCosCutoff
                           ? (e > 0.0 ? pow(cosAngle, e) : 1.0)
                           : 0.0;
            }
        } else {
            vp = normalize(p.xyz);
        }
        float nDotL = max(dot(n, vp), 0.0);
        float spec = 0.0;
        vec3 h = vp + toEye;
        if (nDotL > 0.0 && dot(h, h) > 0.0) {
            float s = gl_FrontMaterial.shininess;
            spec = s > 0.0 ? pow(max(dot(n, normalize(h)), 0.0), s) : 1.0;
        }
        c += att * spot *
             (gl_FrontMaterial.ambient.rgb * gl_LightSource[i].ambient.rgb +
              nDotL * gl_FrontMaterial.diffuse.rgb * gl_LightSource[i].diffuse.rgb +
              spec * gl_FrontMaterial.specular.rgb * gl_LightSource[i].specular.rgb);
    }
    gl_FragColor = vec4(clamp(c, 0.0, 1.0), gl_FrontMaterial.diffuse.a);
}
