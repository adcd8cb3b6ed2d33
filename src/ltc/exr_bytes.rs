//! A table's one EXR layer as bytes, the same table always the same bytes (docs/design.md
//! §2.5): lossless ZIP, written single-threaded. The 2D table and the 4D one both write so.

use std::io::Cursor;

use exr::prelude::*;

/// The bytes of one layer of `size` pixels holding `channels` with `attributes`.
pub fn layer_bytes(
    size: (usize, usize),
    attributes: LayerAttributes,
    channels: SmallVec<[AnyChannel<FlatSamples>; 4]>,
) -> Vec<u8> {
    // ZIP is lossless: the round trip is bit-exact.
    let encoding = Encoding {
        compression: Compression::ZIP16,
        ..Encoding::default()
    };
    let layer = Layer::new(size, attributes, encoding, AnyChannels::sort(channels));
    let mut out = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        // Parallel compression writes chunks in the order they finish: the same table
        // would give different bytes run to run.
        .non_parallel()
        .to_buffered(&mut out)
        .expect("writing an EXR to memory cannot fail");
    out.into_inner()
}
