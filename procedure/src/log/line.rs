//! The fixed-capacity line every writer of the crate fills: no heap, so the pendant
//! formats its export and its link replies into it.

/// The bytes a [`Line`] holds: the widest export line.
pub const LINE_BYTES: usize = 192;

/// A line of output: long enough for the widest export line.
pub type Line = heapless::String<LINE_BYTES>;
