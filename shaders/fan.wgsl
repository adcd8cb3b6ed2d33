// The fan from a pole to a spherical polygon's edges (src/light/fan.rs; docs/design.md
// §1.14): a rect's diffuse lobe in the renders' exact rule. Composed with polar.wgsl, whose
// rule and lobe_value it reads.

// fan_integral: the diffuse lobe over the spherical polygon of unit corners, by the fan from
// the unit pole inside it, n × n nodes an edge (src/light/fan.rs).
fn fan_integral(corners: Polygon, pole: vec3<f32>, n: u32, v: vec3<f32>, alpha: vec2<f32>, f0: f32) -> f32 {
    var total = 0.0;
    for (var k = 0u; k < corners.n; k++) {
        let a = corners.p[k];
        let b = corners.p[(k + 1u) % corners.n];
        let turn = atan2_precise(length(cross(a, b)), dot(a, b));
        if turn > 0.0 {
            let k_sin = 1.0 / sincos_precise(turn).x;
            for (var i = 0u; i < n; i++) {
                let node = rule(n, i);
                let s = 0.5 * (node.x + 1.0);
                let sp = sincos_precise((1.0 - s) * turn);
                let sq = sincos_precise(s * turn);
                let point = (a * sp.x + b * sq.x) * k_sin;
                let along = (b * sq.y - a * sp.y) * (turn * k_sin);
                let sin_b = length(cross(pole, point));
                if sin_b > 0.0 {
                    let u_b = atan2_precise(sin_b, dot(pole, point));
                    let d = (point - pole * dot(pole, point)) / sin_b;
                    let dpsi = dot(pole, cross(point, along)) / (sin_b * sin_b);
                    var radial = 0.0;
                    for (var j = 0u; j < n; j++) {
                        radial += fan_node(pole, d, u_b, rule(n, j), v, alpha, f0);
                    }
                    total += 0.25 * node.y * dpsi * u_b * radial;
                }
            }
        }
    }
    return abs(total);
}

// One node of a fan's meridian: the diffuse lobe at u, weighted by sin u.
fn fan_node(c: vec3<f32>, d: vec3<f32>, u_b: f32, node: vec2<f32>, v: vec3<f32>, alpha: vec2<f32>, f0: f32) -> f32 {
    let su = sincos_precise(0.5 * u_b * (node.x + 1.0));
    return node.y * su.x * lobe_value(v, c * su.y + d * su.x, alpha, f0, 1u);
}
