/* test_plugin_params.c — the plugins' checked reader (plugin_params.h) against a small host of
 * its own: values come through, a misspelt name is the host's error once and then sticky, a
 * failure inside a group or list item is its outer block's, a parameter error after a failed read
 * keeps the first sentence, and a reader without a host keeps the missing name. */
#include "harness.h"
#include "plugin_params.h"

#include <stdarg.h>

/* The host's side: its last sentence and how often it was asked. */
struct sylva_host {
    char msg[512];
    int params_asked, errors;
};

static int test_error(sylva_host *h, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(h->msg, sizeof h->msg, fmt, ap);
    va_end(ap);
    h->errors++;
    return SYLVA_ERR_PARAM;
}

static int test_param_error(sylva_host *h, const sylva_params *p, const char *param, const char *fmt, ...)
{
    (void)p;
    char what[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(h->msg, sizeof h->msg, "'%s': %s", param, what);
    h->errors++;
    return SYLVA_ERR_PARAM;
}

static const sylva_value *test_param(sylva_host *h, const sylva_params *p, const char *name)
{
    h->params_asked++;
    int k = sylva_param_index(p, name);
    if (k >= 0) return &p->values[k];
    test_error(h, "the plugin read parameter '%s', which its schema does not have", name);
    return NULL;
}

static sylva_host_api test_api(void)
{
    return (sylva_host_api){.size = sizeof(sylva_host_api), .abi_major = SYLVA_ABI_MAJOR,
                            .abi_minor = SYLVA_ABI_MINOR, .error = test_error,
                            .param_error = test_param_error, .param = test_param};
}

/* A block: amplitude (real), octaves (int), name (string), item (a group of one real, `scale`). */
static const sylva_param_spec item_spec[] = {{.name = "scale", .type = SYLVA_P_REAL}};
static const sylva_param_spec block_spec[] = {{.name = "amplitude", .type = SYLVA_P_REAL},
                                              {.name = "octaves", .type = SYLVA_P_INT},
                                              {.name = "name", .type = SYLVA_P_STRING},
                                              {.name = "item", .type = SYLVA_P_GROUP, .group = item_spec,
                                               .n_group = 1}};
static const sylva_value item_values[] = {{.is_set = 1, .r = 0.5}};
static const sylva_params item_block = {.spec = item_spec, .n = 1, .values = item_values};
static const sylva_value block_values[] = {{.is_set = 1, .r = 12.5}, {.i = 4}, {.is_set = 1, .s = "ridge"},
                                           {.is_set = 1, .group = &item_block}};
static const sylva_params block = {.spec = block_spec, .n = 4, .values = block_values};

TEST(values_come_through)
{
    sylva_host_api api = test_api();
    sylva_host host = {{0}};
    plugin_params r = plugin_params_open(&api, &host, &block);
    CHECK_NEAR(plugin_param_real(&r, "amplitude"), 12.5, 0);
    CHECK_INT(plugin_param_int(&r, "octaves"), 4);
    CHECK_STR_CONTAINS(plugin_param_str(&r, "name"), "ridge");
    CHECK_INT(plugin_param_given(&r, "octaves"), 0);
    plugin_params g = plugin_params_in(&r, plugin_param(&r, "item")->group);
    CHECK_NEAR(plugin_param_real(&g, "scale"), 0.5, 0);
    CHECK_INT(r.status, SYLVA_OK);
    CHECK_INT(host.errors, 0);
    CHECK_INT(host.params_asked, 6);
}

TEST(a_misspelt_name_is_the_hosts_error_and_sticks)
{
    sylva_host_api api = test_api();
    sylva_host host = {{0}};
    plugin_params r = plugin_params_open(&api, &host, &block);
    const sylva_value *v = plugin_param(&r, "amplitdue");
    CHECK(v != NULL && !v->is_set && v->len == 0 && v->group == NULL && v->items == NULL);
    CHECK(v->list != NULL && v->list[0] == 0 && v->list[1] == 0 && v->list[2] == 0);
    CHECK_INT(r.status, SYLVA_ERR_INTERNAL);
    CHECK_STR_CONTAINS(r.missing, "amplitdue");
    CHECK_STR_CONTAINS(host.msg, "read parameter 'amplitdue'");
    CHECK_NEAR(plugin_param_real(&r, "amplitude"), 0, 0); /* after a failure the host is not asked */
    CHECK(plugin_param_str(&r, "nmae") == NULL);
    CHECK_INT(host.params_asked, 1);
    CHECK_INT(host.errors, 1);
    CHECK_STR_CONTAINS(host.msg, "'amplitdue'");
}

TEST(a_failure_in_a_group_is_its_outer_blocks)
{
    sylva_host_api api = test_api();
    sylva_host host = {{0}};
    plugin_params r = plugin_params_open(&api, &host, &block);
    plugin_params g = plugin_params_in(&r, plugin_param(&r, "item")->group);
    plugin_param_real(&g, "sclae");
    CHECK_INT(g.status, SYLVA_ERR_INTERNAL);
    CHECK_INT(r.status, SYLVA_ERR_INTERNAL);
    CHECK_STR_CONTAINS(r.missing, "sclae");
    /* a group read from a failed reader is no block: its reads fail without asking the host */
    plugin_params none = plugin_params_in(&r, plugin_param(&r, "item")->group);
    CHECK(none.block == NULL);
    plugin_param_real(&none, "scale");
    CHECK_INT(host.errors, 1);
}

TEST(a_parameter_error_after_a_failed_read_keeps_the_first_sentence)
{
    sylva_host_api api = test_api();
    sylva_host host = {{0}};
    plugin_params r = plugin_params_open(&api, &host, &block);
    CHECK_INT(plugin_params_error(&r, "octaves", "octaves %d is too many", 40), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(host.msg, "'octaves': octaves 40 is too many");
    plugin_param_int(&r, "octave");
    CHECK_INT(plugin_params_error(&r, "octaves", "octaves %d is too many", 40), SYLVA_ERR_INTERNAL);
    CHECK_STR_CONTAINS(host.msg, "read parameter 'octave'");
    plugin_err err = {.status = SYLVA_ERR_PARAM, .msg = "a model's sentence"};
    CHECK_INT(plugin_params_report(&r, &err), SYLVA_ERR_INTERNAL);
    CHECK_STR_CONTAINS(host.msg, "read parameter 'octave'");
}

TEST(without_a_host_the_missing_name_is_kept)
{
    plugin_params r = plugin_params_open(NULL, NULL, &block);
    CHECK_INT(plugin_param_int(&r, "octaves"), 4);
    CHECK_INT(r.status, SYLVA_OK);
    CHECK_NEAR(plugin_param_real(&r, "amplitdue"), 0, 0);
    CHECK_INT(r.status, SYLVA_ERR_INTERNAL);
    CHECK_STR_CONTAINS(r.missing, "amplitdue");
}

TEST_LIST(TEST_CASE(values_come_through), TEST_CASE(a_misspelt_name_is_the_hosts_error_and_sticks),
          TEST_CASE(a_failure_in_a_group_is_its_outer_blocks),
          TEST_CASE(a_parameter_error_after_a_failed_read_keeps_the_first_sentence),
          TEST_CASE(without_a_host_the_missing_name_is_kept))
