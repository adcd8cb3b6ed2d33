// Rect lights (docs/design.md §1.11), mirroring src/light/rect/mod.rs, src/light/rect/polygon.rs
// and src/light/rect/quadrature.rs by name. Composed after brdf.wgsl, ltc.wgsl and
// sphere_light.wgsl (uses atan_precise, illuminance_sphere, gl8, mirror and
// sphere_ltc_point's arithmetic).

// The light buffer's code for a rect (src/gpu/light/mod.rs shape_constant).
const SHAPE_RECT: u32 = 2u;

// How a side shades a rect (src/light/rect/mod.rs RectMethod; rect_light.rs rect_constant).
const RECT_EXACT: u32 = 0u;          // the BRDF over the rect above the surface
const RECT_LTC_POLYGON: u32 = 1u;    // Heitz et al. 2016: clipped, M⁻¹, Lambert's edge formula
const RECT_LTC_PROXY: u32 = 2u;      // Heitz & Hill 2017: the sphere of the same form factor
const RECT_LTC_PROXY_FAST: u32 = 3u; // three.js's closed form of the proxy
const RECT_LTC_POINT: u32 = 4u;      // the centre as an oriented point light

// Some light is a rect, and how A and B shade rects: constants, so that a pipeline holds only
// the methods it uses (the exact one's loops would weigh on every other's registers).
override RECTS: bool = false;
override RECT_A: u32 = RECT_LTC_POLYGON;
override RECT_B: u32 = RECT_EXACT;

// Rect: centre and half-edges in the shading frame, relative to the shading point; it emits
// toward u × v.
struct Rect {
    centre: vec3<f32>,
    u: vec3<f32>,
    v: vec3<f32>,
}

// A convex polygon of up to 6 corners (the exact rule's rect clipped at the horizon: 5; each
// clip adds one corner at most).
struct Polygon {
    p: array<vec3<f32>, 6>,
    n: u32,
}

// RECT_POINT_LIMIT: below this angular size a rect is shaded as its oriented point light
// (src/light/rect/mod.rs: the edge sum's f32 rounding, ~2⁻²⁴ d/s of the value, stays ≤ 6e-5).
const RECT_POINT_LIMIT: f32 = 1e-3;

// Rect::corners: c − u − v, c + u − v, c + u + v, c − u + v.
fn rect_corners(r: Rect) -> Polygon {
    var poly: Polygon;
    poly.p[0] = r.centre - r.u - r.v;
    poly.p[1] = r.centre + r.u - r.v;
    poly.p[2] = r.centre + r.u + r.v;
    poly.p[3] = r.centre - r.u + r.v;
    poly.n = 4u;
    return poly;
}

// Rect::faces_origin.
fn rect_faces_origin(r: Rect) -> bool {
    return dot(r.centre, cross(r.u, r.v)) < 0.0;
}

// Rect::area: 4 |u × v|.
fn rect_area(r: Rect) -> f32 {
    return 4.0 * length(cross(r.u, r.v));
}

// Rect::angular_size: (|u| + |v|) / |c|.
fn rect_angular_size(r: Rect) -> f32 {
    return (length(r.u) + length(r.v)) / length(r.centre);
}

// Rect::point_irradiance: A cos θe / d² at unit radiance.
fn rect_point_irradiance(r: Rect) -> f32 {
    let d2 = dot(r.centre, r.centre);
    let cos_e = -dot(normalize(cross(r.u, r.v)), r.centre) / sqrt(d2);
    return rect_area(r) * max(cos_e, 0.0) / d2;
}

// clip_horizon: the part of the polygon with z ≥ 0 (Sutherland–Hodgman against one plane).
fn clip_horizon(poly: Polygon) -> Polygon {
    var out: Polygon;
    out.n = 0u;
    for (var k = 0u; k < poly.n; k++) {
        let a = poly.p[k];
        let b = poly.p[(k + 1u) % poly.n];
        if a.z >= 0.0 {
            polygon_push(&out, a);
        }
        if (a.z >= 0.0) != (b.z >= 0.0) {
            let t = a.z / (a.z - b.z);
            let x = a + (b - a) * t;
            polygon_push(&out, vec3<f32>(x.x, x.y, 0.0));
        }
    }
    return out;
}

// A corner after the polygon's last, written at a constant index (polar.wgsl's "Writes").
fn polygon_push(poly: ptr<function, Polygon>, x: vec3<f32>) {
    let at = (*poly).n;
    for (var k = 0u; k < 6u; k++) {
        if k == at {
            (*poly).p[k] = x;
        }
    }
    (*poly).n = at + 1u;
}

// atan2(y, x) for y ≥ 0 by atan_precise: the angle in [0, π].
fn atan2_precise(y: f32, x: f32) -> f32 {
    if x > 0.0 {
        return atan_precise(y / x);
    }
    if x < 0.0 {
        return PI - atan_precise(y / -x);
    }
    return PI / 2.0;
}

// edge_vector: θ_e n̂_e of one edge, from the corners themselves (a × b and
// atan2(|a × b|, a·b)): unit directions would leave a small polygon's cross products ε/θ_e of
// relative precision.
fn edge_vector(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    let c = cross(a, b);
    let len = length(c);
    if len == 0.0 {
        return vec3<f32>(0.0);
    }
    return c * (atan2_precise(len, dot(a, b)) / len);
}

// A rect's four corners (rect_corners' first four), unclipped.
alias Quad = array<vec3<f32>, 4>;

// The corners of a rect as a Quad.
fn rect_quad(r: Rect) -> Quad {
    return Quad(r.centre - r.u - r.v, r.centre + r.u - r.v, r.centre + r.u + r.v, r.centre - r.u + r.v);
}

// The quad mapped by m and scaled to a largest component of 1: the formulas below do not see
// the scale, and far or mapped corners would overflow f32's |a × b|².
fn map_quad(m: mat3x3<f32>, q: Quad) -> Quad {
    var out: Quad;
    var big = 0.0;
    for (var k = 0u; k < 4u; k++) {
        out[k] = m * q[k];
        let a = abs(out[k]);
        big = max(big, max(a.x, max(a.y, a.z)));
    }
    if big > 0.0 {
        for (var k = 0u; k < 4u; k++) {
            out[k] /= big;
        }
    }
    return out;
}

// vector_form_factor: (1/2π) Σ θ_e n̂_e of a quad.
fn vector_form_factor(q: Quad) -> vec3<f32> {
    var sum = vec3<f32>(0.0);
    for (var k = 0u; k < 4u; k++) {
        sum += edge_vector(q[k], q[(k + 1u) % 4u]);
    }
    return -sum / (2.0 * PI);
}

// paper_scale: the printed eq. 25 drops D's 1/π.
fn paper_scale(integral: f32, normalization: u32) -> f32 {
    if normalization == NORMALIZATION_PAPER_LITERAL {
        return PI * integral;
    }
    return integral;
}

// Cut: the part t ∈ [t0, t1] of an edge that is kept, and the horizon (1 the surface's, 2 the
// cosine's, 0 none) that cut each end (src/light/rect/polygon.rs).
struct Cut {
    t0: f32,
    t1: f32,
    plane0: u32,
    plane1: u32,
}

// Cut::cut: what of c keeps a height going from f0 to f1 at or above 0, cut by `plane`.
fn cut(c: Cut, f0: f32, f1: f32, plane: u32) -> Cut {
    var out = c;
    if f0 < 0.0 && f1 < 0.0 {
        out.t0 = 1.0;
        out.t1 = 0.0;
    } else if f0 < 0.0 {
        let t = f0 / (f0 - f1);
        if t > out.t0 {
            out.t0 = t;
            out.plane0 = plane;
        }
    } else if f1 < 0.0 {
        let t = f0 / (f0 - f1);
        if t < out.t1 {
            out.t1 = t;
            out.plane1 = plane;
        }
    }
    return out;
}

// horizons_meet: where both horizons are clipped at, the direction where they meet (the
// original ẑ × r mapped, r the last row of M⁻¹, or its opposite) that the mapped quad holds;
// w = 0 where there is none.
fn horizons_meet(m: mat3x3<f32>, mapped: Quad, clip: u32) -> vec4<f32> {
    if clip != (CLIP_HORIZON | CLIP_TRANSFORMED) {
        return vec4<f32>(0.0);
    }
    let r = vec3<f32>(m[0].z, m[1].z, m[2].z);
    let line = m * vec3<f32>(-r.y, r.x, 0.0);
    if all(line == vec3<f32>(0.0)) {
        return vec4<f32>(0.0);
    }
    let centre = mapped[0] + mapped[1] + mapped[2] + mapped[3];
    var inside_plus = true;
    var inside_minus = true;
    for (var k = 0u; k < 4u; k++) {
        let normal = cross(mapped[k], mapped[(k + 1u) % 4u]);
        let side = dot(normal, centre);
        inside_plus = inside_plus && dot(normal, line) * side >= 0.0;
        inside_minus = inside_minus && -dot(normal, line) * side >= 0.0;
    }
    if inside_plus {
        return vec4<f32>(line, 1.0);
    }
    if inside_minus {
        return vec4<f32>(-line, 1.0);
    }
    return vec4<f32>(0.0);
}

// A path along the horizons from e (left by horizon `left_by`) to s (come back by
// `back_by`): straight on one horizon, else through where they meet.
fn along(e: vec3<f32>, left_by: u32, s: vec3<f32>, back_by: u32, meet: vec4<f32>) -> vec3<f32> {
    if meet.w > 0.0 && left_by != back_by {
        return edge_vector(e, meet.xyz) + edge_vector(meet.xyz, s);
    }
    return edge_vector(e, s);
}

// ltc_polygon: ∫ D over the quad — clipped at the surface's horizon (case 1) and, after M⁻¹,
// at the cosine's (case 2), edge by edge with the paths along the horizons between where it
// leaves and comes back, Lambert's edge formula; M⁻¹ with a negative determinant turns the
// polygon over.
fn ltc_polygon(ltc: Ltc, q: Quad, clip: u32, normalization: u32) -> f32 {
    let m = ltc.cos_from_brdf;
    let mapped = map_quad(m, q);
    let meet = horizons_meet(m, mapped, clip);
    var sum = vec3<f32>(0.0);
    var left = vec4<f32>(0.0);       // xyz where it last left, w its horizon (0: none)
    var first_back = vec4<f32>(0.0); // xyz where it first came back, w its horizon
    for (var k = 0u; k < 4u; k++) {
        let j = (k + 1u) % 4u;
        var range = Cut(0.0, 1.0, 0u, 0u);
        if (clip & CLIP_HORIZON) != 0u {
            range = cut(range, q[k].z, q[j].z, 1u);
        }
        if (clip & CLIP_TRANSFORMED) != 0u {
            range = cut(range, mapped[k].z, mapped[j].z, 2u);
        }
        if range.t0 <= range.t1 {
            let a = mapped[k];
            let b = mapped[j];
            let x0 = a + (b - a) * range.t0;
            let x1 = a + (b - a) * range.t1;
            if range.t0 > 0.0 {
                if left.w > 0.0 {
                    sum += along(left.xyz, u32(left.w), x0, range.plane0, meet);
                    left.w = 0.0;
                } else {
                    first_back = vec4<f32>(x0, f32(range.plane0));
                }
            }
            sum += edge_vector(x0, x1);
            if range.t1 < 1.0 {
                left = vec4<f32>(x1, f32(range.plane1));
            }
        }
    }
    if left.w > 0.0 && first_back.w > 0.0 {
        sum += along(left.xyz, u32(left.w), first_back.xyz, u32(first_back.w), meet);
    }
    let turn = sign(determinant(m));
    var integral = -turn * sum.z / (2.0 * PI);
    // Clipped, the integral is ≥ 0: what rounding leaves below it is 0.
    if (clip & CLIP_TRANSFORMED) != 0u {
        integral = max(integral, 0.0);
    }
    return paper_scale(integral, normalization);
}

// mapped_form_factor: the vector form factor of M⁻¹P, turned back over where M⁻¹ turns it.
fn mapped_form_factor(ltc: Ltc, q: Quad) -> vec3<f32> {
    return sign(determinant(ltc.cos_from_brdf)) * vector_form_factor(map_quad(ltc.cos_from_brdf, q));
}

// proxy_sphere: the cap of the same vector form factor, clipped at the horizon (Heitz & Hill 2017).
fn proxy_sphere(f: vec3<f32>) -> f32 {
    let len = length(f);
    if len == 0.0 {
        return 0.0;
    }
    return illuminance_sphere(f.z / len, min(len, 1.0)) / PI;
}

// proxy_sphere_fast: three.js's LTC_ClippedSphereFormFactor.
fn proxy_sphere_fast(f: vec3<f32>) -> f32 {
    let len = length(f);
    return max((len * len + f.z) / (len + 1.0), 0.0);
}

// ltc_proxy: the unclipped vector form factor of M⁻¹P through proxy_sphere (case 2), or its z.
fn ltc_proxy(ltc: Ltc, q: Quad, clip: u32, normalization: u32) -> f32 {
    let f = mapped_form_factor(ltc, q);
    var integral = f.z;
    if (clip & CLIP_TRANSFORMED) != 0u {
        integral = proxy_sphere(f);
    }
    return paper_scale(integral, normalization);
}

// ltc_proxy_fast: ltc_proxy with proxy_sphere_fast.
fn ltc_proxy_fast(ltc: Ltc, q: Quad, clip: u32, normalization: u32) -> f32 {
    let f = mapped_form_factor(ltc, q);
    var integral = f.z;
    if (clip & CLIP_TRANSFORMED) != 0u {
        integral = proxy_sphere_fast(f);
    }
    return paper_scale(integral, normalization);
}

// One rect of unit radiance at one shading point (src/light/rect/mod.rs RectShading).
struct RectShading {
    pixel: EmitterShading,
    rect: Rect,
}

// rect_emitter_lobes: a rect's unit-radiance lobes by `method` (RECT_*) and its area, for
// emitter.wgsl's emitter_lobes (src/light/rect/mod.rs emitter_lobes): centred at `centre`, its
// half-edges `dims`' first two xyz, both mapped to the shading frame by `to_frame`.
fn rect_emitter_lobes(
    method: u32,
    dims: mat2x4<f32>,
    centre: vec3<f32>,
    to_frame: mat3x3<f32>,
    pixel: EmitterShading,
    pair: LtcPair,
) -> vec3<f32> {
    let rect = Rect(to_frame * centre, to_frame * dims[0].xyz, to_frame * dims[1].xyz);
    return vec3<f32>(rect_light(method, RectShading(pixel, rect), pair), rect_area(rect));
}

// rect_point: the oriented point light at the centre — the exact point light for the exact
// method, the paper's point formula for the LTC ones.
fn rect_point(s: RectShading, pair: LtcPair, exact: bool) -> vec2<f32> {
    let l = normalize(s.rect.centre);
    return emitter_shading_point_light(s.pixel, pair, l, rect_point_irradiance(s.rect), exact);
}

// rect_rule: both lobes of a rect of unit radiance by the renders' rule (src/light/rect/
// region.rs, docs/design.md §1.14): the specular lobe by the polar rule, the diffuse lobe by
// the fan from the corners' mean.
fn rect_rule(s: RectShading) -> vec2<f32> {
    let above = clip_horizon(rect_corners(s.rect));
    var corners: Polygon;
    corners.n = 0u;
    var sum = vec3<f32>(0.0);
    for (var k = 0u; k < above.n; k++) {
        let p = above.p[k];
        if dot(p, p) > 0.0 {
            polygon_push(&corners, normalize(p));
            sum += normalize(p);
        }
    }
    if corners.n < 3u {
        return vec2<f32>(0.0);
    }
    let middle = normalize(sum);
    let polar = polygon_polar(corners, middle, mirror(s.pixel.v), s.pixel.v, s.pixel.alpha, s.pixel.f0);
    let lobe = lobe_within(lobe_specular(polar.pole, s.pixel.v, s.pixel.alpha), polar.bounds, middle);
    return vec2<f32>(
        polar_integral(polar, lobe, rule_nodes(s.pixel.alpha), s.pixel.v, s.pixel.alpha, s.pixel.f0, 0u),
        fan_integral(corners, middle, DIFFUSE_NODES, s.pixel.v, s.pixel.alpha, s.pixel.f0),
    );
}

// polygon_polar: the convex spherical polygon of unit corners as a polar region, its pole at
// focus where it holds it, else at its edges' brightest point, cut at every corner and at the
// feet of the perpendiculars from the pole to its edges (src/light/rect/region.rs).
fn polygon_polar(
    corners: Polygon,
    middle: vec3<f32>,
    focus: vec3<f32>,
    v: vec3<f32>,
    alpha: vec2<f32>,
    f0: f32,
) -> Polar {
    var bounds: Bounds;
    bounds.count = 0u;
    bounds.cap = vec4<f32>(0.0, 0.0, 0.0, -1.0);
    var edges: array<Arc, 5>;
    for (var k = 0u; k < corners.n; k++) {
        let a = corners.p[k];
        let b = corners.p[(k + 1u) % corners.n];
        let c = cross(a, b);
        if dot(c, c) > 0.0 && bounds.count < MAX_PLANES {
            let n = normalize(c);
            // Written at a constant index (polar.wgsl's "Writes").
            for (var e = 0u; e < MAX_PLANES; e++) {
                if e == bounds.count {
                    edges[e] = Arc(a, b, vec3<f32>(0.0), vec4<f32>(0.0));
                }
            }
            bounds_push(&bounds, select(n, -n, dot(n, middle) < 0.0));
        }
    }
    var pole = focus;
    if !bounds_contains(bounds, focus) {
        let best = brightest(edges, bounds.count, v, alpha, f0);
        pole = arc_at(edges[u32(best.x)], best.y);
    }
    var polar = polar_new(bounds, pole, 2u);
    for (var k = 0u; k < corners.n; k++) {
        polar_cut_toward(&polar, corners.p[k]);
    }
    for (var k = 0u; k < bounds.count; k++) {
        let n = bounds.planes[k];
        let foot = pole - n * dot(n, pole);
        if dot(foot, foot) > 0.0 {
            let f = normalize(foot);
            let a = edges[k].a;
            let b = edges[k].b;
            let turn = cross(a, b);
            if dot(cross(a, f), turn) > 0.0 && dot(cross(f, b), turn) > 0.0 {
                polar_cut_foot(&polar, n);
            }
        }
    }
    return polar;
}

// rect_light: both lobes of a rect of unit radiance by `method` (RECT_* of plane.wgsl): 0
// facing away, its point light below RECT_POINT_LIMIT.
fn rect_light(method: u32, s: RectShading, pair: LtcPair) -> vec2<f32> {
    if !rect_faces_origin(s.rect) {
        return vec2<f32>(0.0);
    }
    if rect_angular_size(s.rect) < RECT_POINT_LIMIT {
        return rect_point(s, pair, method == RECT_EXACT);
    }
    let corners = rect_quad(s.rect);
    switch method {
        case RECT_EXACT: { return rect_rule(s); }
        case RECT_LTC_POLYGON: {
            return lobe_weights(pair, s.pixel.f0, s.pixel.normalization) * vec2<f32>(
                ltc_polygon(pair.spec, corners, s.pixel.clip, s.pixel.normalization),
                ltc_polygon(pair.diff, corners, s.pixel.clip, s.pixel.normalization),
            );
        }
        case RECT_LTC_PROXY: {
            return lobe_weights(pair, s.pixel.f0, s.pixel.normalization) * vec2<f32>(
                ltc_proxy(pair.spec, corners, s.pixel.clip, s.pixel.normalization),
                ltc_proxy(pair.diff, corners, s.pixel.clip, s.pixel.normalization),
            );
        }
        case RECT_LTC_PROXY_FAST: {
            return lobe_weights(pair, s.pixel.f0, s.pixel.normalization) * vec2<f32>(
                ltc_proxy_fast(pair.spec, corners, s.pixel.clip, s.pixel.normalization),
                ltc_proxy_fast(pair.diff, corners, s.pixel.clip, s.pixel.normalization),
            );
        }
        default: { return rect_point(s, pair, false); }
    }
}
