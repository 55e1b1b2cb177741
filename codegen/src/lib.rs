//! The `airlight` tool as a library: scene records as JSON lines ([`scene_json`]) and their
//! evaluation ([`eval`]), the GPU check ([`verify`]) and the pictures ([`render`]). The shaders
//! themselves (emission, record layout, wgpu runner, agreement criterion) are the
//! `airlight-shaders` crate.

pub mod eval;
pub mod render;
pub mod scene_json;
pub mod verify;
