/* test_wp_forest.c — a forest of Weber-Penn species costs per plant what a forest of the other
 * tree plugins' species costs: 100,000 plants of four species of the species library (California
 * black oak, quaking aspen, tamarack, European larch; bench/forest_weber_penn.yaml) and 100,000
 * of the main job's four (beech and spruce by the vessel model, maple by Aono-Kunii, the shrub by
 * the L-system), 4 age variants each, on the same terrain, rendered through the renderer's path
 * at the same picture (bench/bench_forest_memory.h, which bench_scale --compare prints). Each
 * forest is built in a child process of its own at 10,000 and at 100,000 plants; what an
 * instance costs apart from its prototype is the growth of the peak resident memory over the
 * 90,000 plants added (the species, their BVHs, lights and film are the same at both counts).
 *
 * The bound: the Weber-Penn forest's bytes per instance at most 1.1 times the other forest's.
 * An instance is its record, an Embree instance of its prototype's BVH, a crown proxy and its
 * share of the top BVH, none of which depends on which plugin grew the prototype or how large it
 * is, so the two agree but for the measurement's noise (runs of both forests differ by up to 3 %:
 * 513 to 529 and 517 to 521 bytes); an overhead of a plugin's own per plant, a second Embree
 * instance or a copy of anything per plant, would add 300 bytes or more. Both figures must also
 * hold at least the instance record, so that a measurement that saw nothing cannot pass.
 *
 * Linux (it reads /proc/self and forks); skipped under AddressSanitizer, whose allocator and
 * quarantine the resident memory would then measure. Slow: 25 to 40 s on 2 cores. */
#include <stdio.h>

#include "bench_forest_memory.h"
#include "harness.h"

#if defined(__SANITIZE_ADDRESS__)
#define WP_FOREST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WP_FOREST_SANITIZED 1
#endif
#endif

#define PLANTS 100000u
#define FEWER 10000u
#define VARIANTS 4u
#define BOUND 1.1

/* The bytes an instance of plan's forest costs; -1 when it could not be measured. */
static double bytes_per_instance(const bench_forest_plan *plan)
{
    bench_forest_figures fewer, more;
    err_buf err = {{0}};
    if (bench_forest_measure_apart(plan, FEWER, VARIANTS, 2, 160, 90, 1, stdout, &fewer, &err) ||
        bench_forest_measure_apart(plan, PLANTS, VARIANTS, 2, 160, 90, 1, stdout, &more, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    double bytes = bench_forest_bytes_per_instance(&fewer, &more);
    printf("%s: %u prototypes, %llu triangles; %u plants: peak %.0f MiB, species alone %.0f MiB; %.1f B per "
           "instance\n\n", plan->name, more.prototypes, (unsigned long long)more.triangles, PLANTS, more.peak_mib,
           more.species_mib, bytes);
    return bytes;
}

TEST(instances_cost_what_the_others_cost)
{
#ifdef WP_FOREST_SANITIZED
    SKIP("resident memory under AddressSanitizer is its allocator's");
#endif
    double others = bytes_per_instance(&bench_forest_main);
    double weber_penn = bytes_per_instance(&bench_forest_weber_penn);
    printf("bytes per instance: Weber-Penn %.1f, the other plugins' %.1f (bound %.2f times)\n", weber_penn, others,
           BOUND);
    CHECK(others >= (double)sizeof(instance));
    CHECK(weber_penn >= (double)sizeof(instance));
    CHECK(weber_penn <= BOUND * others);
}

TEST_LIST(TEST_CASE(instances_cost_what_the_others_cost))
