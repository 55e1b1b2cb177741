// The entry point both GPU-benchmark baselines (gauss_angle.wgsl, raymarch.wgsl) share, appended
// after the baseline by codegen/benches/gpu.rs: the generated `airlight_main`'s bindings (records
// at 0, 8-byte results at 1), workgroup size 64, each record through the baseline's
// `baseline_in_scatter`.

@group(0) @binding(0) var<storage, read> airlight_records: array<AirlightScene>;
@group(0) @binding(1) var<storage, read_write> airlight_results: array<AirlightResult>;

// A baseline's value as a result: status 2 (and the largest f32) if it is not finite, else 0.
fn baseline_result(value: f32) -> AirlightResult {
    if ((bitcast<u32>(value) & 0x7f800000u) == 0x7f800000u) {
        return AirlightResult(3.40282347e38, 2u);
    }
    return AirlightResult(value, 0u);
}

@compute @workgroup_size(64)
fn airlight_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= arrayLength(&airlight_records)) {
        return;
    }
    airlight_results[i] = baseline_in_scatter(airlight_records[i]);
}
