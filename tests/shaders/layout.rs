//! What Rust hands the shaders has the WGSL's shape: the Pod types' layouts are the WGSL
//! structs', and the bindings Rust lists are the WGSL's, by group, binding and kind.

use ltc_lab::gpu::scene::{GpuLight, Params};
use ltc_lab::gpu::{bin_module_source, plane_module_source};

use crate::validate;

/// A Rust type's fields' offsets and its size, as `wgsl_layout` gives a WGSL struct's.
macro_rules! rust_layout {
    ($t:ty, $($field:ident),*) => {
        (vec![$((stringify!($field).to_string(), std::mem::offset_of!($t, $field) as u32)),*],
         std::mem::size_of::<$t>() as u32)
    };
}

/// `(member name, byte offset)` of a WGSL struct, and its size, as naga lays it out.
fn wgsl_layout(module: &naga::Module, name: &str) -> (Vec<(String, u32)>, u32) {
    let ty = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no struct {name}"))
        .1;
    match &ty.inner {
        naga::TypeInner::Struct { members, span } => (
            members
                .iter()
                .map(|m| (m.name.clone().unwrap(), m.offset))
                .collect(),
            *span,
        ),
        other => panic!("{name} is {other:?}"),
    }
}

#[test]
fn pod_types_match_the_wgsl_structs() {
    let module = validate("plane", &plane_module_source(false));
    assert_eq!(
        rust_layout!(
            Params,
            eye,
            forward,
            right,
            up,
            base_color,
            alpha,
            f0,
            tan_half_fov,
            aspect,
            half_size,
            divider,
            probe_x,
            probe_y,
            width,
            height,
            light_count,
            lut_size,
            clip,
            normalization,
            tiles_x,
            tiles_y,
            light_start,
            light_end,
            cull,
            tile_capacity,
            lut_size_b,
            lut_base_b,
            lut_base,
            bin_row,
            alpha_y,
            tangent_x,
            tangent_y,
            aniso_pad,
            aniso_a,
            aniso_dims_a,
            aniso_b,
            aniso_dims_b
        ),
        wgsl_layout(&module, "Params")
    );
    assert_eq!(
        rust_layout!(GpuLight, position_range, intensity),
        wgsl_layout(&module, "GpuLight")
    );
}

/// What a WGSL global bound in group 0 is, in `binding::Kind`'s terms.
fn kind_of(module: &naga::Module, var: &naga::GlobalVariable) -> ltc_lab::gpu::binding::Kind {
    use ltc_lab::gpu::binding::Kind;
    match (var.space, &module.types[var.ty].inner) {
        (naga::AddressSpace::Uniform, _) => Kind::Uniform,
        (naga::AddressSpace::Storage { access }, _)
            if access.contains(naga::StorageAccess::STORE) =>
        {
            Kind::ReadWrite
        }
        (naga::AddressSpace::Storage { .. }, _) => Kind::Read,
        (_, naga::TypeInner::Image { class, .. }) => match class {
            naga::ImageClass::Storage { format, .. } => Kind::WrittenTexture(match format {
                naga::StorageFormat::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
                naga::StorageFormat::Rgba8Unorm => wgpu::TextureFormat::Rgba8Unorm,
                other => panic!("a storage texture of {other:?}"),
            }),
            _ => Kind::Texture,
        },
        other => panic!("{:?} is bound as {other:?}", var.name),
    }
}

/// Each shader module's bindings as Rust lists them (and makes its layout and bind groups
/// from) are exactly the WGSL's: the same numbers, variables and kinds, none missing.
#[test]
fn the_bindings_rust_lists_are_the_wgsl_ones() {
    use ltc_lab::gpu::binding::Binding;
    use ltc_lab::gpu::{bin, display, plane};
    let modules: [(&str, String, &[Binding]); 4] = [
        ("plane", plane_module_source(false), &plane::BINDINGS),
        (
            "plane with f16",
            plane_module_source(true),
            &plane::BINDINGS,
        ),
        ("bin", bin_module_source(), &bin::BINDINGS),
        ("display", display::SOURCE.to_string(), &display::BINDINGS),
    ];
    for (name, src, listed) in modules {
        let module = validate(name, &src);
        let mut wgsl: Vec<Binding> = module
            .global_variables
            .iter()
            .filter_map(|(_, v)| {
                let b = v.binding.as_ref()?;
                assert_eq!(b.group, 0, "{name}: {:?} is not in group 0", v.name);
                let var = v.name.clone().unwrap_or_default();
                let listed_name = listed
                    .iter()
                    .find(|l| l.name == var)
                    .unwrap_or_else(|| panic!("{name}: Rust does not list {var}"))
                    .name;
                Some(Binding {
                    number: b.binding,
                    name: listed_name,
                    kind: kind_of(&module, v),
                })
            })
            .collect();
        wgsl.sort_by_key(|b| b.number);
        let mut rust = listed.to_vec();
        rust.sort_by_key(|b| b.number);
        assert_eq!(rust, wgsl, "{name}");
    }
}
