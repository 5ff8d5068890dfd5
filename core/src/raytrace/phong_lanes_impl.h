// PhongModel::directLanes' loop, written once for any lane width: phong_model.cpp includes
// this file twice, inside namespace avxlanes (four lanes, compiled for AVX) and inside
// sse2lanes (two lanes, baseline x86-64). Each of those lanes headers gives the names used
// here: kWidth, the types D/V/Mask, splat, sqrtOf, the comparisons, maskBits, gather,
// loadLanes, storeLanes. No include guard, no includes: it is a body, not a header.
//
// Every lane computes direct()'s formula for its hit with the same IEEE operations in the
// same order (the scalar comments are direct()'s and lightFactors'), so a lane's colour is
// direct()'s bit for bit; only which lanes call std::pow depends on the width's masks.

// Whether the highlight's pow can reach the colour, lane by lane: direct() adds
// transmittance · (diffuse·colour + s·ks·colour) with s = pow(cos, shininess), finite and
// >= 0 for a cos >= 0 and a shininess clamped to [0, 128] (a NaN cos needs an infinite or
// NaN normal, whose diffuse term makes the colour non-finite either way). With ks = ±0 the
// product s·ks is the same zero for any such s, and with transmittance = ±0 (shadowed or
// facing away) the whole term is a zero for any s (a NaN or infinity from the colours stays
// one either way): s = 0 then gives the same colour, at most a zero of the other sign,
// which no byte sees. A NaN shininess (clamp keeps it) makes s NaN: pow is called as before.
// A NaN transmittance or ks counts as nonzero (the unordered comparison). The eye hits of
// balls 4's floor (ks = 0) and its shadowed hits made most of the eye level's pow calls.
inline Mask specularNeeded(D transmittance, D ks, D shininess) {
    const D zero = splat(0.0);
    return maskOr(maskAnd(notEqualOrNaN(transmittance, zero), notEqualOrNaN(ks, zero)),
                  isNaN(shininess));
}

inline void directGroups(const Scene& scene, const Ray* views, const Hit* hits, unsigned lanes,
                         const double* transmittance, Color* out) {
    static_assert(kMaxPacket % kWidth == 0, "a packet is shaded kWidth lanes at a time");
    constexpr unsigned kGroupBits = (1u << kWidth) - 1u;
    for (int i = 0; i < kMaxPacket; i += kWidth) {
        const unsigned groupMask = (lanes >> i) & kGroupBits;
        if (!groupMask) continue;
        // A lane outside `lanes` computes on the group's first lane's data (never NaN from
        // garbage) and is not written.
        const int first = i + __builtin_ctz(groupMask);
        int at[kWidth];
        const Hit* h[kWidth];
        const Material* m[kWidth];
        double sh[kWidth];
        bool oneMaterial = true;
        for (int k = 0; k < kWidth; ++k) {
            at[k] = ((groupMask >> k) & 1u) ? i + k : first;
            h[k] = &hits[at[k]];
            m[k] = &scene.materials[size_t(h[k]->material)];
            sh[k] = std::clamp(m[k]->phongExp, 0.0, 128.0);
            oneMaterial = oneMaterial && m[k] == m[0];
        }
        // The material's terms: broadcast when the group's lanes share one material (a row
        // of eye hits mostly does: balls 4's spheres, its floor), gathered otherwise.
        const auto qm = [&](auto field) { return oneMaterial ? splat(field(0)) : gather(field); };
        // direct()'s material terms: ambient = ka·colour, diffuse = kd·colour, specular(ks).
        const V surface = qm([&](int k) { return m[k]->colour; });
        const V ambient = qm([&](int k) { return m[k]->ka; }) * surface,
                diffuse = qm([&](int k) { return m[k]->kd; }) * surface;
        const D ks = qm([&](int k) { return m[k]->ks; });
        const V specular{ks, ks, ks};
        const D shininess = gather([&](int k) { return sh[k]; });
        V c = qm([&](int k) { return m[k]->emission; }) + ambient * splat(scene.globalAmbient);
        const V origin = gather([&](int k) { return views[at[k]].origin; });
        const V pos = gather([&](int k) { return h[k]->point; }) - origin;
        const V normal = gather([&](int k) { return h[k]->normal; });
        const D zero = splat(0.0);
        const V zero3{zero, zero, zero};
        // eyeDirection(true, pos) = unit(−pos).
        const V toViewer = {-pos.x, -pos.y, -pos.z};
        const D eyeLen = sqrtOf(dot(toViewer, toViewer));
        const V toEye = select(greater(eyeLen, zero), toViewer / eyeLen, zero3);
        for (std::size_t li = 0; li < scene.lights.size(); ++li) {
            const Light& l = scene.lights[li];
            // lightFactors for a point light (w = 1) without a spot: gl.position =
            // l.position − view.origin.
            const V toLight = (splat(l.position) - origin) - pos;
            const D d = sqrtOf(dot(toLight, toLight));
            const V vp = select(greater(d, zero), toLight / d, zero3);
            const D denom = splat(l.constantAttenuation) + splat(l.linearAttenuation) * d +
                            splat(l.quadraticAttenuation) * d * d;
            const D one = splat(1.0);
            const D attenuation = select(equal(denom, one), one, one / maxOf(denom, splat(1e-12)));
            const D diffuseFactor = maxOf(dot(normal, vp), zero);
            const double* trLight = &transmittance[li * kMaxPacket];
            const D trans = groupMask == kGroupBits ? loadLanes(&trLight[i])
                                                    : gather([&](int k) { return trLight[at[k]]; });
            // The lanes whose pow reaches the colour: lightFactors' dv != 0 && len > 0 and
            // specularNeeded; the half vector only when a lane may need it (the floor's
            // groups, ks = 0, and the shadowed ones skip it).
            const Mask mayNeed =
                maskAnd(notEqualOrNaN(diffuseFactor, zero), specularNeeded(trans, ks, shininess));
            alignas(32) double spec[kWidth] = {};
            if (maskBits(mayNeed)) {
                const V half = vp + toEye;
                const D len = sqrtOf(dot(half, half));
                const D cosH = maxOf(dot(normal, half / len), zero);
                alignas(32) double cv[kWidth];
                storeLanes(cv, cosH);
                for (unsigned powLanes = maskBits(maskAnd(mayNeed, greater(len, zero))); powLanes;
                     powLanes &= powLanes - 1) {
                    const int k = __builtin_ctz(powLanes);
                    spec[k] = std::pow(cv[k], sh[k]);
                }
            }
            const D specularFactor = loadLanes(spec);
            const V lightColour = splat(l.colour);
            // attenuation · spot (1 without a cone) · (ambient·l.ambient + shadow ·
            // (diffuse·d·colour + specular·s·colour)), as direct() groups it.
            c = c + (attenuation * one) * (ambient * splat(l.ambient) +
                                           trans * ((diffuseFactor * diffuse) * lightColour +
                                                    (specularFactor * specular) * lightColour));
        }
        alignas(32) double cx[kWidth], cy[kWidth], cz[kWidth];
        storeLanes(cx, c.x);
        storeLanes(cy, c.y);
        storeLanes(cz, c.z);
        for (int k = 0; k < kWidth; ++k)
            if ((groupMask >> k) & 1u) out[i + k] = Color(cx[k], cy[k], cz[k]);
    }
}
