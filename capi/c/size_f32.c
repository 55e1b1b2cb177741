/* Links the f32 entry points only (capi/size.sh measures what they pull in). */
#include "airlight.h"

int main(void) {
    AirlightSceneF32 s = {0};
    AirlightIntervalF32 lit = {0.0f, 1.0f};
    AirlightResultF32 a = airlight_in_scatter_f32(&s);
    AirlightResultF32 b = airlight_in_scatter_lit_f32(&s, &lit, 1);
    return (int)(a.value + b.value);
}
