/* test_cli_status.c — the exit status follows from the kind of failure alone (cli_status.h,
 * README "exit status"), whatever the call site guessed; a sentence's place is kept beside it;
 * the host tells a plugin its kind of failure from the status, not from the text. */
#include "harness.h"

#include "cli/cli_status.h"
#include "scene_build/host.h"
#include "scene/mesh.h"
#include "scene/scene.h"

TEST(exit_status_of_each_kind)
{
    CHECK_INT(cli_exit_status(ERR_USAGE), 1);
    CHECK_INT(cli_exit_status(ERR_INPUT), 2);
    CHECK_INT(cli_exit_status(ERR_LIMIT), 2);
    CHECK_INT(cli_exit_status(ERR_PLUGIN), 2);
    CHECK_INT(cli_exit_status(ERR_OUTPUT), 3);
    CHECK_INT(cli_exit_status(ERR_NOMEM), 4);
    CHECK_INT(cli_exit_status(ERR_INTERNAL), 4);
    CHECK_INT(cli_exit_status(ERR_UNSTATED), 4);
}

/* A call site that expects bad input (2) or an unwritten file (3) still ends with 4 when the
 * failure below it was running out of memory, and its own kind applies only when none was
 * stated. */
TEST(stated_kind_wins_over_the_call_site)
{
    err_buf e = {{0}};
    err_nomem(&e, "out of memory adding instance %u", 7);
    CHECK_INT(cli_fail("test", &e, ERR_INPUT), 4);
    err_nomem(&e, "out of memory");
    CHECK_INT(cli_fail("test", &e, ERR_OUTPUT), 4);
    err_set(&e, "cannot write");
    CHECK_INT(cli_fail("test", &e, ERR_OUTPUT), 3);
    err_set(&e, "bad value");
    CHECK_INT(cli_fail(NULL, &e, ERR_INPUT), 2);
    CHECK_INT(cli_failf("test", ERR_PLUGIN, "plugin %s failed", "x"), 2);
}

TEST(place_beside_the_sentence)
{
    err_buf e = {{0}};
    err_at(&e, ERR_INPUT, "scene.yaml", 3, 14, "'%s' must be positive", "spacing");
    CHECK(!strcmp(e.msg, "scene.yaml:3:14: 'spacing' must be positive"));
    CHECK(!strcmp(err_sentence(&e), "'spacing' must be positive"));
    CHECK(err_has_place(&e));
    CHECK(!strcmp(e.file, "scene.yaml"));
    CHECK_INT(e.line, 3);
    CHECK_INT(e.column, 14);
    CHECK_INT(e.status, ERR_INPUT);
    /* A placed sentence keeps its more precise place; an unplaced one gets the block's. */
    err_locate(&e, "scene.yaml", 1, 1);
    CHECK(!strcmp(e.msg, "scene.yaml:3:14: 'spacing' must be positive"));
    err_nomem(&e, "out of memory");
    CHECK(!err_has_place(&e));
    err_prefix(&e, "object '%s': ", "mast");
    err_locate(&e, "scene.yaml", 9, 3);
    CHECK(!strcmp(e.msg, "scene.yaml:9:3: object 'mast': out of memory"));
    CHECK_INT(e.status, ERR_NOMEM);
    /* err_set forgets what a former sentence said about its kind and place. */
    err_set(&e, "plain");
    CHECK_INT(e.status, ERR_UNSTATED);
    CHECK(!err_has_place(&e));
    CHECK(!strcmp(err_sentence(&e), "plain"));
}

/* mesh_append's limit reaches the plugin as SYLVA_ERR_LIMIT (from the status, not the words),
 * and a bad triangle as SYLVA_ERR_PARAM. */
TEST(host_passes_the_kind_on)
{
    scene *s = scene_new();
    err_buf err = {{0}};
    sylva_host h;
    host_init(&h, s, "/tmp", 1, "tree plugin 'x'", &err);
    mesh *m = mesh_new();
    const float pos[3] = {0, 0, 0};
    const uint32_t tri[3] = {0, 0, 5};
    CHECK_INT(host_api_table()->mesh_append(&h, m, pos, NULL, NULL, MESH_MAX_VERTICES + 1u, NULL, NULL, 0),
              SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(err.msg, "per-mesh limit");
    CHECK_INT(host_api_table()->mesh_append(&h, m, pos, NULL, NULL, 1, tri, NULL, 1), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "uses vertex 5");
    CHECK_INT(h.out_of_memory, 0);
    mesh_free(m);
    host_release(&h);
    scene_free(s);
}

TEST_LIST(TEST_CASE(exit_status_of_each_kind), TEST_CASE(stated_kind_wins_over_the_call_site),
          TEST_CASE(place_beside_the_sentence), TEST_CASE(host_passes_the_kind_on))
