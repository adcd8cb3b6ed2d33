//! The bindings of the compute passes, written once as data: each shader module lists its
//! bindings (`@binding` number, the WGSL variable, what it holds), its bind group layout is
//! made from that list, and `tests/shaders/main.rs` checks the list against the WGSL. Every
//! binding is seen by the compute stage only, and buffers are bound whole.

/// What a binding holds, as its WGSL declaration says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `var<uniform>`.
    Uniform,
    /// `var<storage, read>`.
    Read,
    /// `var<storage, read_write>`.
    ReadWrite,
    /// `texture_2d<f32>`, read with `textureLoad` (not filtered).
    Texture,
    /// `texture_storage_2d<format, write>`.
    WrittenTexture(wgpu::TextureFormat),
}

/// One binding of group 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Binding {
    pub number: u32,
    /// The WGSL variable bound there.
    pub name: &'static str,
    pub kind: Kind,
}

/// A binding, for the lists' brevity.
pub const fn binding(number: u32, name: &'static str, kind: Kind) -> Binding {
    Binding { number, name, kind }
}

/// The bind group layout of `bindings`.
pub fn layout(device: &wgpu::Device, label: &str, bindings: &[Binding]) -> wgpu::BindGroupLayout {
    let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings.iter().map(entry).collect();
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &entries,
    })
}

fn entry(b: &Binding) -> wgpu::BindGroupLayoutEntry {
    let buffer = |ty| wgpu::BindingType::Buffer {
        ty,
        has_dynamic_offset: false,
        min_binding_size: None,
    };
    let ty = match b.kind {
        Kind::Uniform => buffer(wgpu::BufferBindingType::Uniform),
        Kind::Read => buffer(wgpu::BufferBindingType::Storage { read_only: true }),
        Kind::ReadWrite => buffer(wgpu::BufferBindingType::Storage { read_only: false }),
        Kind::Texture => wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: false },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        Kind::WrittenTexture(format) => wgpu::BindingType::StorageTexture {
            access: wgpu::StorageTextureAccess::WriteOnly,
            format,
            view_dimension: wgpu::TextureViewDimension::D2,
        },
    };
    wgpu::BindGroupLayoutEntry {
        binding: b.number,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty,
        count: None,
    }
}

impl Binding {
    /// A bind group's entry: `buffer` bound whole here.
    pub fn buffer<'a>(&self, buffer: &'a wgpu::Buffer) -> wgpu::BindGroupEntry<'a> {
        wgpu::BindGroupEntry {
            binding: self.number,
            resource: buffer.as_entire_binding(),
        }
    }

    /// A bind group's entry: `view` bound here.
    pub fn texture<'a>(&self, view: &'a wgpu::TextureView) -> wgpu::BindGroupEntry<'a> {
        wgpu::BindGroupEntry {
            binding: self.number,
            resource: wgpu::BindingResource::TextureView(view),
        }
    }
}
