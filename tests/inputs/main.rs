//! Input from anyone, checked where it enters (docs/design.md §5.11, §5.13): lessons as files,
//! the lab's view links, and methods loaded from WGSL files.

mod lesson;
mod method_file;
mod view_link;
