/* Links the f32 and the f64 entry points (capi/size.sh measures what they pull in). */
#include "airlight.h"

int main(void) {
    AirlightSceneF32 s = {0};
    AirlightSceneF64 d = {0};
    AirlightIntervalF32 lit = {0.0f, 1.0f};
    AirlightIntervalF64 lit64 = {0.0, 1.0};
    AirlightResultF32 a = airlight_in_scatter_f32(&s);
    AirlightResultF32 b = airlight_in_scatter_lit_f32(&s, &lit, 1);
    AirlightResultF64 c = airlight_in_scatter_f64(&d);
    AirlightResultF64 e = airlight_in_scatter_lit_f64(&d, &lit64, 1);
    return (int)(a.value + b.value + c.value + e.value);
}
