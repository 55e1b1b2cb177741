// ---------------------------------------------------------------- compute entry point
// One invocation per record: records[i] → results[i]; workgroup size: layout.rs WORKGROUP_SIZE.

@group(0) @binding(0) var<storage, read> airlight_records: array<AirlightScene>;
@group(0) @binding(1) var<storage, read_write> airlight_results: array<AirlightResult>;

@compute @workgroup_size(@WORKGROUP_SIZE@)
fn airlight_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= arrayLength(&airlight_records)) {
        return;
    }
    airlight_results[i] = airlight_in_scatter(airlight_records[i]);
}
