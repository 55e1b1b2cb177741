//! The `airlight` tool as a library: scene records (JSON lines) and their evaluation on the
//! CPU kernel; shader emission through naga (for build scripts); the GPU backend.

pub mod agreement;
pub mod eval;
pub mod gpu;
pub mod layout;
pub mod render;
pub mod targets;
pub mod verify;
pub mod scene_json;
