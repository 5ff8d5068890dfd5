#version 120
// Blinn bump mapping (section 1.5.2), fragment stage. The surface p(s, t) is only imagined
// displaced by D(s, t) = depth · h(repeats · (s, t)) along n; its normal is (5.14):
//   m ≈ p_s × p_t + D_s (n × p_t) − D_t (n × p_s).
// With T = p_s/|p_s|, B = p_t/|p_t| and n = T × B this is, divided by |p_s||p_t|,
//   m = n − (D_s/|p_s|) T − (D_t/|p_t|) B.
// D_s and D_t come from the height map by central differences (the text's divided
// differences). Only the normal changes: the geometry, hence the silhouette, stays smooth.
uniform sampler2D heightMap;
uniform vec2 repeats;   // height-map tiles along s and t
uniform vec2 texelSize; // 1/width, 1/height of the height map
uniform float depth;    // displacement for h = 1, object units (0 = the smooth surface)

varying vec3 vPos;
varying vec3 vNormal;
varying vec3 vTangent;
varying vec2 vScale;
varying vec2 vTex;

float height(vec2 uv) { return texture2D(heightMap, uv).r; }

void main() {
    vec2 uv = vTex * repeats;
    float hs = (height(uv + vec2(texelSize.x, 0.0)) - height(uv - vec2(texelSize.x, 0.0))) /
               (2.0 * texelSize.x);
    float ht = (height(uv + vec2(0.0, texelSize.y)) - height(uv - vec2(0.0, texelSize.y))) /
               (2.0 * texelSize.y);
    float ds = depth * repeats.x * hs; // ∂D/∂s by the chain rule through uv = repeats · (s, t)
    float dt = depth * repeats.y * ht;

    vec3 n = normalize(vNormal);
    vec3 t = normalize(vTangent - n * dot(n, vTangent)); // re-orthogonalised after interpolation
    vec3 b = cross(n, t);
    vec3 m = normalize(n - (ds / max(vScale.x, 1e-6)) * t - (dt / max(vScale.y, 1e-6)) * b);

    // Phong with the fixed-function lights 0..3 and material, as in fig. 5.20 (four white
    // lights and a weak ambient).
    vec3 v = normalize(-vPos);
    vec4 colour = gl_FrontMaterial.emission + gl_LightModel.ambient * gl_FrontMaterial.ambient;
    for (int i = 0; i < 4; ++i) {
        vec4 lp = gl_LightSource[i].position;
        vec3 l = normalize(lp.w == 0.0 ? lp.xyz : lp.xyz - vPos);
        float diffuse = max(dot(m, l), 0.0);
        float specular = 0.0;
        if (diffuse > 0.0)
            specular = pow(max(dot(reflect(-l, m), v), 0.0), gl_FrontMaterial.shininess);
        colour += gl_LightSource[i].ambient * gl_FrontMaterial.ambient +
                  diffuse * gl_LightSource[i].diffuse * gl_FrontMaterial.diffuse +
                  specular * gl_LightSource[i].specular * gl_FrontMaterial.specular;
    }
    gl_FragColor = vec4(colour.rgb, 1.0);
}
