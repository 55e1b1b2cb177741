/* The C ABI against the mpmath references: every scene of tests/reference/classes.jsonl,
 * handed over by tests/tests/capi.rs as one line of plain numbers each (argv[1]), evaluated
 * through airlight.h in f64 and in f32 and checked to the kernel's targets
 * (docs/DESIGN.md §8): |x − exact| / max(|exact|, tau·scale) <= tau, tau = 1e-10 in f64 and
 * 1e-4 in f32 (f32 only where the value is at least 1e-30). Then the contract at the edges:
 * a null scene, an invalid field, a light on the segment, lit sub-segments.
 * Exit status 0 when everything holds; each failure is printed. */
#include "airlight.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond, ...)                                                                  \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            failures++;                                                                   \
            printf("FAIL %s:%d: ", __FILE__, __LINE__);                                   \
            printf(__VA_ARGS__);                                                          \
            printf("\n");                                                                 \
        }                                                                                 \
    } while (0)

static double err(double x, double exact, double tau, double scale) {
    return fabs(x - exact) / fmax(fabs(exact), tau * scale);
}

static AirlightSceneF32 to_f32(const AirlightSceneF64 *s) {
    AirlightSceneF32 t;
    for (int i = 0; i < 3; i++) {
        t.ray.origin[i] = (float)s->ray.origin[i];
        t.ray.dir[i] = (float)s->ray.dir[i];
        t.light.position[i] = (float)s->light.position[i];
        t.light.distribution.axis[i] = (float)s->light.distribution.axis[i];
    }
    t.ray.t_min = (float)s->ray.t_min;
    t.ray.t_max = (float)s->ray.t_max;
    t.light.intensity = (float)s->light.intensity;
    t.light.distribution.kind = s->light.distribution.kind;
    t.light.distribution.power = s->light.distribution.power;
    t.light.distribution.cos_inner = (float)s->light.distribution.cos_inner;
    t.light.distribution.cos_outer = (float)s->light.distribution.cos_outer;
    t.medium.sigma_s = (float)s->medium.sigma_s;
    t.medium.sigma_t = (float)s->medium.sigma_t;
    t.phase.kind = s->phase.kind;
    t.phase.g = (float)s->phase.g;
    t.phase.k = (float)s->phase.k;
    t.phase.g1 = (float)s->phase.g1;
    t.phase.g2 = (float)s->phase.g2;
    t.phase.w = (float)s->phase.w;
    return t;
}

static int references(const char *path) {
    FILE *f = fopen(path, "r");
    if (!f) {
        printf("cannot open %s\n", path);
        return 1;
    }
    char category[64];
    double exact, scale, worst64 = 0.0, worst32 = 0.0;
    int scenes = 0, scenes32 = 0;
    AirlightSceneF64 s;
    memset(&s, 0, sizeof s);
    AirlightDistributionF64 *d = &s.light.distribution;
    while (fscanf(f, "%63s %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %u %u %lf %lf %lf %lf %lf %lf %lf %u %lf %lf %lf %lf %lf",
                  category, &exact, &scale, &s.ray.origin[0], &s.ray.origin[1], &s.ray.origin[2], &s.ray.dir[0],
                  &s.ray.dir[1], &s.ray.dir[2], &s.ray.t_min, &s.ray.t_max, &s.light.position[0], &s.light.position[1],
                  &s.light.position[2], &s.light.intensity, &d->kind, &d->power, &d->axis[0], &d->axis[1], &d->axis[2],
                  &d->cos_inner, &d->cos_outer, &s.medium.sigma_s, &s.medium.sigma_t, &s.phase.kind, &s.phase.g,
                  &s.phase.k, &s.phase.g1, &s.phase.g2, &s.phase.w) == 30) {
        scenes++;
        AirlightResultF64 r = airlight_in_scatter_f64(&s);
        CHECK(r.status == AIRLIGHT_STATUS_OK, "%s #%d: f64 status %u (%s)", category, scenes, r.status, r.message);
        /* below f64's normal range there is no f64 to compare with: 0 or subnormal is right */
        double e = exact < DBL_MIN ? (r.value < DBL_MIN ? 0.0 : INFINITY) : err(r.value, exact, 1e-10, scale);
        worst64 = fmax(worst64, e);
        CHECK(e <= 1e-10, "%s #%d: f64 error %.2e (got %.17g, exact %.17g)", category, scenes, e, r.value, exact);
        if (exact >= 1e-30) {
            scenes32++;
            AirlightSceneF32 s32 = to_f32(&s);
            AirlightResultF32 r32 = airlight_in_scatter_f32(&s32);
            CHECK(r32.status == AIRLIGHT_STATUS_OK, "%s #%d: f32 status %u (%s)", category, scenes, r32.status, r32.message);
            double e32 = err((double)r32.value, exact, 1e-4, scale);
            worst32 = fmax(worst32, e32);
            CHECK(e32 <= 1e-4, "%s #%d: f32 error %.2e (got %.9g, exact %.17g)", category, scenes, e32, r32.value, exact);
        }
    }
    fclose(f);
    printf("references: %d scenes in f64 (largest error %.2e), %d in f32 (largest error %.2e)\n", scenes, worst64, scenes32, worst32);
    CHECK(scenes >= 300, "only %d scenes read from %s", scenes, path);
    return 0;
}

static void edges(void) {
    /* a null scene is a status, not a crash */
    AirlightResultF32 r = airlight_in_scatter_f32(NULL);
    CHECK(r.status == AIRLIGHT_STATUS_NULL_POINTER && r.value == 0.0f, "null scene: status %u", r.status);

    AirlightSceneF32 s = {
        .ray = {.origin = {0, 0, 0}, .dir = {2, 0, 0}, .t_min = 0, .t_max = INFINITY},
        .light = {.position = {5, 1, 0}, .intensity = 100, .distribution = {.kind = AIRLIGHT_LIGHT_OMNI}},
        .medium = {.sigma_s = 0.08f, .sigma_t = 0.1f},
        .phase = {.kind = AIRLIGHT_PHASE_HENYEY_GREENSTEIN, .g = 0.9f},
    };
    AirlightResultF32 ok = airlight_in_scatter_f32(&s);
    CHECK(ok.status == AIRLIGHT_STATUS_OK && ok.value > 0.0f && ok.message[0] == 0, "valid scene: status %u value %g", ok.status, ok.value);

    /* an invalid field is named */
    AirlightSceneF32 bad = s;
    bad.phase.g = 1.5f;
    r = airlight_in_scatter_f32(&bad);
    CHECK(r.status == AIRLIGHT_STATUS_INVALID && r.value == 0.0f && strncmp(r.message, "phase.g: ", 9) == 0,
          "g = 1.5: status %u, message '%s'", r.status, r.message);
    bad = s;
    bad.phase.kind = 77;
    r = airlight_in_scatter_f32(&bad);
    CHECK(r.status == AIRLIGHT_STATUS_INVALID && strncmp(r.message, "phase.kind: ", 12) == 0, "kind 77: '%s'", r.message);

    /* the light on the segment: +inf */
    AirlightSceneF32 on = s;
    on.light.position[1] = 0.0f;
    r = airlight_in_scatter_f32(&on);
    CHECK(r.status == AIRLIGHT_STATUS_INFINITE && isinf(r.value), "light on the segment: status %u value %g", r.status, r.value);

    /* lit sub-segments: the whole ray as one part is the plain call; two halves add up with
     * the second attenuated, to the f32 target (1e-4 of each part) */
    AirlightIntervalF32 whole = {0.0f, INFINITY};
    r = airlight_in_scatter_lit_f32(&s, &whole, 1);
    CHECK(r.status == AIRLIGHT_STATUS_OK && r.value == ok.value, "lit whole: %g vs %g", r.value, ok.value);
    AirlightIntervalF32 halves[2] = {{0.0f, 5.0f}, {5.0f, INFINITY}};
    AirlightResultF32 first = airlight_in_scatter_lit_f32(&s, &halves[0], 1);
    AirlightResultF32 both = airlight_in_scatter_lit_f32(&s, halves, 2);
    CHECK(first.value < both.value && fabs(both.value - ok.value) <= 2e-4 * ok.value, "lit halves: %g + … = %g vs %g", first.value, both.value, ok.value);
    r = airlight_in_scatter_lit_f32(&s, NULL, 0);
    CHECK(r.status == AIRLIGHT_STATUS_OK && r.value == 0.0f, "no lit part: status %u value %g", r.status, r.value);
    r = airlight_in_scatter_lit_f32(&s, NULL, 3);
    CHECK(r.status == AIRLIGHT_STATUS_NULL_POINTER, "null lit with count 3: status %u", r.status);
}

int main(int argc, char **argv) {
    if (argc != 2) {
        printf("usage: %s SCENES.txt\n", argv[0]);
        return 2;
    }
    if (references(argv[1]))
        return 1;
    edges();
    printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
