/* gltf_layout.c — the buffers, buffer views and accessors of a glTF 2.0 file checked against one
 * another and its bytes, and its primitives, skins, nodes and animations against what Assimp
 * reads of them unchecked (gltf_layout.h). */
#include "model/gltf_layout.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model_limits.h"
#include "util/json_read.h"

typedef struct layout {
    json_doc d;
    const char *where;
    err_buf *err;
} layout;

/* -1 with err set at value v of the JSON: "where:L:C: what". */
static int fail(layout *l, uint32_t v, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(layout *l, uint32_t v, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    uint32_t line, column;
    json_line_column(&l->d, l->d.values[v].at, &line, &column);
    return err_fail(l->err, ERR_INPUT, "%s:%u:%u: %s", l->where, line, column, what);
}

/* The whole number of member key of object o into *out: dflt when the member is absent and dflt
 * is not -1 (an absent member is refused when it is); otherwise it must be a whole number from lo
 * to hi. what names the object in messages ("accessor 5"). */
static int whole(layout *l, uint32_t o, const char *key, int64_t dflt, uint64_t lo, uint64_t hi, const char *what,
                 uint64_t *out)
{
    uint32_t m = json_member(&l->d, o, key);
    if (!m) {
        if (dflt >= 0) return *out = (uint64_t)dflt, 0;
        return fail(l, o, "%s has no \"%s\"; a glTF 2.0 file gives one", what, key);
    }
    if (json_whole(&l->d, m, out) && *out >= lo && *out <= hi) return 0;
    const json_value *v = &l->d.values[m];
    uint32_t shown = v->kind == JSON_STRING ? v->len + 2 : v->kind == JSON_ARRAY || v->kind == JSON_OBJECT ? 1 : v->len;
    return fail(l, m, "%s's \"%s\" is %.*s%s; a whole number from %llu to %llu, written with digits alone, is valid",
                what, key, (int)(shown > 24 ? 24 : shown), l->d.text + v->at, shown > 24 ? "..." : "",
                (unsigned long long)lo, (unsigned long long)hi);
}

/* The array of member key of the root, its item count in *count (0 when absent). */
static int array(layout *l, const char *key, uint32_t *arr, uint32_t *count)
{
    *count = 0;
    *arr = json_member(&l->d, 0, key);
    if (!*arr) return 0;
    if (l->d.values[*arr].kind != JSON_ARRAY) return fail(l, *arr, "\"%s\" is not an array", key);
    for (uint32_t v = l->d.values[*arr].first; v; v = l->d.values[v].next) {
        if (l->d.values[v].kind != JSON_OBJECT) return fail(l, v, "item %u of \"%s\" is not an object", *count, key);
        (*count)++;
    }
    return 0;
}

static unsigned component_size(uint64_t type)
{
    switch (type) {
    case 5120: case 5121: return 1; /* BYTE, UNSIGNED_BYTE */
    case 5122: case 5123: return 2; /* SHORT, UNSIGNED_SHORT */
    case 5125: case 5126: return 4; /* UNSIGNED_INT, FLOAT */
    default: return 0;
    }
}

/* The components of the accessor type v ("VEC3": 3), 0 when it is none of glTF's. */
static unsigned type_components(const layout *l, uint32_t v)
{
    static const struct { const char *name; unsigned n; } types[] = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
    for (size_t k = 0; k < sizeof types / sizeof types[0]; k++)
        if (json_string_is(&l->d, v, types[k].name)) return types[k].n;
    return 0;
}

/* The bytes each buffer holds as the reader takes them, into held[] (n_buffers): a GLB's buffer 0
 * is its BIN chunk, whatever the JSON states of it; another, its byteLength, which the reader
 * holds the buffer's data to. */
static int check_buffers(layout *l, uint64_t bin, uint32_t buffers, uint32_t n_buffers, uint64_t *held)
{
    char what[48];
    uint32_t v = l->d.values[buffers].first;
    for (uint32_t i = 0; i < n_buffers; i++, v = l->d.values[v].next) {
        snprintf(what, sizeof what, "buffer %u", i);
        if (bin != GLTF_NO_BIN && i == 0) held[i] = bin;
        else if (whole(l, v, "byteLength", -1, 1, 1ull << 53, what, &held[i])) return -1;
    }
    return 0;
}

/* Each view's buffer and bytes checked against the bytes its buffer holds (held[], n_buffers);
 * the views' lengths and strides kept in view_len[] and view_stride[] (n_views each). */
static int check_views(layout *l, uint32_t views, uint32_t n_views, const uint64_t *held, uint32_t n_buffers,
                       uint64_t *view_len, uint64_t *view_stride)
{
    char what[48];
    uint32_t v = l->d.values[views].first;
    for (uint32_t i = 0; i < n_views; i++, v = l->d.values[v].next) {
        uint64_t b, offset, length;
        snprintf(what, sizeof what, "buffer view %u", i);
        if (!n_buffers) return fail(l, v, "%s names a buffer, and the file has none", what);
        if (whole(l, v, "buffer", -1, 0, n_buffers - 1, what, &b) ||
            whole(l, v, "byteOffset", 0, 0, 1ull << 53, what, &offset) ||
            whole(l, v, "byteLength", -1, 1, 1ull << 53, what, &length) ||
            whole(l, v, "byteStride", 0, 0, 252, what, &view_stride[i]))
            return -1;
        if (view_stride[i] && (view_stride[i] < 4 || view_stride[i] % 4))
            return fail(l, json_member(&l->d, v, "byteStride"), "%s's byteStride is %llu; a multiple of 4 from 4 "
                        "to 252 is valid", what, (unsigned long long)view_stride[i]);
        if (offset + length > held[b])
            return fail(l, v, "%s takes bytes %llu to %llu of buffer %llu, which holds %llu; a view lies within its "
                        "buffer (a GLB's buffer 0 is its BIN chunk): export the model again", what,
                        (unsigned long long)offset, (unsigned long long)(offset + length), (unsigned long long)b,
                        (unsigned long long)held[b]);
        view_len[i] = length;
    }
    return 0;
}

/* Each accessor (its value's index in accessor[], n_accessors) within its view. */
static int check_accessors(layout *l, const uint32_t *accessor, uint32_t n_accessors, uint32_t n_views,
                           const uint64_t *view_len, const uint64_t *view_stride)
{
    char what[48];
    for (uint32_t i = 0; i < n_accessors; i++) {
        uint32_t a = accessor[i];
        snprintf(what, sizeof what, "accessor %u", i);
        uint32_t sparse = json_member(&l->d, a, "sparse");
        if (sparse)
            return fail(l, sparse, "%s is sparse, whose indices the model reader writes by without checking "
                        "them; export the model without sparse accessors (morph targets and shape keys off)", what);
        uint64_t component, count, offset, view;
        if (whole(l, a, "componentType", -1, 5120, 5126, what, &component) ||
            whole(l, a, "count", -1, 1, UINT32_MAX, what, &count) ||
            whole(l, a, "byteOffset", 0, 0, 1ull << 53, what, &offset))
            return -1;
        unsigned size = component_size(component);
        if (!size)
            return fail(l, json_member(&l->d, a, "componentType"), "%s's componentType is %llu; valid are 5120, "
                        "5121, 5122, 5123, 5125 and 5126", what, (unsigned long long)component);
        uint32_t type = json_member(&l->d, a, "type");
        if (!type) return fail(l, a, "%s has no \"type\"; a glTF 2.0 file gives one", what);
        unsigned components = type_components(l, type);
        if (!components)
            return fail(l, type, "%s's type is not one of \"SCALAR\", \"VEC2\", \"VEC3\", \"VEC4\", \"MAT2\", "
                        "\"MAT3\" and \"MAT4\"", what);
        if (!json_member(&l->d, a, "bufferView")) continue; /* all zeros, which the reader refuses */
        if (!n_views) return fail(l, a, "%s names a buffer view, and the file has none", what);
        if (whole(l, a, "bufferView", -1, 0, n_views - 1, what, &view)) return -1;
        uint64_t element = (uint64_t)size * components;
        uint64_t stride = view_stride[view] ? view_stride[view] : element;
        uint64_t end = offset + (count - 1) * stride + element; /* below 2^63: each term is */
        if (end > view_len[view])
            return fail(l, a, "%s reads bytes %llu to %llu of buffer view %llu (%llu elements of %llu bytes, "
                        "%llu apart), which holds %llu; an accessor lies within its view: export the model again",
                        what, (unsigned long long)offset, (unsigned long long)end, (unsigned long long)view,
                        (unsigned long long)count, (unsigned long long)element, (unsigned long long)stride,
                        (unsigned long long)view_len[view]);
    }
    return 0;
}

/* The accessor index of member key of object o (an attribute or "indices") into *out, checked
 * against n_accessors; *out = UINT32_MAX when the member is absent. what names o in messages. */
static int accessor_ref(layout *l, uint32_t o, const char *key, uint32_t n_accessors, const char *what, uint32_t *out)
{
    uint64_t i;
    *out = UINT32_MAX;
    if (!json_member(&l->d, o, key)) return 0;
    if (!n_accessors) return fail(l, o, "%s names an accessor, and the file has none", what);
    if (whole(l, o, key, -1, 0, n_accessors - 1, what, &i)) return -1;
    *out = (uint32_t)i;
    return 0;
}

/* Each mesh primitive draws enough vertices for its mode: Assimp 5.2 makes count - 2 faces of a
 * triangle fan or strip and count - 1 of a line strip and then writes the first whatever that
 * came to (a fan of two indices wrote a face into an array of none; one index asked for 2^64
 * faces); its indices are an unsigned integer scalar, as the spec says. The accessors
 * (accessor[], n_accessors, their values) have been checked before. */
static int check_primitives(layout *l, const uint32_t *accessor, uint32_t n_accessors)
{
    static const char *const modes[] = {"points", "lines", "a line loop", "a line strip", "triangles",
                                        "a triangle strip", "a triangle fan"};
    static const uint64_t least[] = {1, 2, 2, 2, 3, 3, 3};
    uint32_t meshes, n_meshes;
    if (array(l, "meshes", &meshes, &n_meshes)) return -1;
    char what[64];
    uint32_t m = l->d.values[meshes].first;
    for (uint32_t i = 0; i < n_meshes; i++, m = l->d.values[m].next) {
        uint32_t prims = json_member(&l->d, m, "primitives");
        if (!prims) continue;
        if (l->d.values[prims].kind != JSON_ARRAY) return fail(l, prims, "mesh %u's \"primitives\" is not an array", i);
        uint32_t k = 0;
        for (uint32_t p = l->d.values[prims].first; p; p = l->d.values[p].next, k++) {
            snprintf(what, sizeof what, "mesh %u primitive %u", i, k);
            if (l->d.values[p].kind != JSON_OBJECT) return fail(l, p, "%s is not an object", what);
            uint64_t mode, count;
            uint32_t attributes = json_member(&l->d, p, "attributes"), position, indices;
            if (whole(l, p, "mode", 4, 0, 6, what, &mode)) return -1;
            if (!attributes || l->d.values[attributes].kind != JSON_OBJECT)
                return fail(l, p, "%s has no \"attributes\" object; a primitive gives its POSITION there", what);
            if (accessor_ref(l, attributes, "POSITION", n_accessors, what, &position) ||
                accessor_ref(l, p, "indices", n_accessors, what, &indices))
                return -1;
            if (position == UINT32_MAX) return fail(l, attributes, "%s has no POSITION attribute", what);
            uint32_t a = accessor[indices != UINT32_MAX ? indices : position];
            if (whole(l, a, "count", -1, 1, UINT32_MAX, "the accessor", &count)) return -1;
            if (indices != UINT32_MAX) {
                uint64_t component;
                if (whole(l, a, "componentType", -1, 5120, 5126, "the accessor", &component)) return -1;
                if (!json_string_is(&l->d, json_member(&l->d, a, "type"), "SCALAR") ||
                    (component != 5121 && component != 5123 && component != 5125))
                    return fail(l, a, "accessor %u, the indices of %s, is not a SCALAR of componentType 5121, 5123 "
                                "or 5125 (an unsigned byte, short or int)", indices, what);
            }
            if (count < least[mode])
                return fail(l, p, "%s draws %s of %llu %s, and %s needs at least %llu; leave the primitive out or "
                            "export it again", what, modes[mode], (unsigned long long)count,
                            count == 1 ? "vertex" : "vertices", modes[mode], (unsigned long long)least[mode]);
        }
    }
    return 0;
}

/* Each node's skin is one of the file's, and each skin has inverse bind matrices, a MAT4 of
 * floats for every joint: Assimp 5.2 looks a node's skin up without checking its index, reads
 * the matrices of a skin a node uses without looking whether it has any (a skin without them
 * crashed the program) and reads one for each joint whatever their count. node[] (n_nodes)
 * holds the nodes' values. */
static int check_skins(layout *l, const uint32_t *accessor, uint32_t n_accessors, const uint32_t *node,
                       uint32_t n_nodes)
{
    uint32_t skins, n_skins;
    if (array(l, "skins", &skins, &n_skins)) return -1;
    char what[48];
    uint32_t v = l->d.values[skins].first;
    for (uint32_t i = 0; i < n_skins; i++, v = l->d.values[v].next) {
        snprintf(what, sizeof what, "skin %u", i);
        uint32_t matrices, joints = json_member(&l->d, v, "joints"), n_joints = 0;
        if (joints && l->d.values[joints].kind != JSON_ARRAY) return fail(l, joints, "%s's joints are not an array", what);
        for (uint32_t j = joints ? l->d.values[joints].first : 0; j; j = l->d.values[j].next) n_joints++;
        if (accessor_ref(l, v, "inverseBindMatrices", n_accessors, what, &matrices)) return -1;
        if (matrices == UINT32_MAX)
            return fail(l, v, "%s has no inverseBindMatrices, without which the model reader crashes; sylva draws "
                        "no skins: export the model without its armature, or with its bind matrices", what);
        uint32_t a = accessor[matrices];
        uint64_t count, component;
        if (whole(l, a, "count", -1, 1, UINT32_MAX, "the accessor", &count) ||
            whole(l, a, "componentType", -1, 5120, 5126, "the accessor", &component))
            return -1;
        if (!json_string_is(&l->d, json_member(&l->d, a, "type"), "MAT4") || component != 5126 || count < n_joints)
            return fail(l, a, "accessor %u, the inverse bind matrices of %s, is not %u MAT4 of floats (5126), one "
                        "for each joint", matrices, what, n_joints);
    }
    for (uint32_t i = 0; i < n_nodes; i++) {
        uint64_t skin;
        if (!json_member(&l->d, node[i], "skin")) continue;
        snprintf(what, sizeof what, "node %u", i);
        if (!n_skins) return fail(l, node[i], "%s names a skin, and the file has none", what);
        if (whole(l, node[i], "skin", -1, 0, n_skins - 1, what, &skin)) return -1;
    }
    return 0;
}

/* The children array of node i checked, its first item (0 when none) returned in *first. */
static int children_of(layout *l, const uint32_t *node, uint32_t i, uint32_t *first)
{
    uint32_t children = json_member(&l->d, node[i], "children");
    if (children && l->d.values[children].kind != JSON_ARRAY)
        return fail(l, children, "node %u's children are not an array", i);
    *first = children ? l->d.values[children].first : 0;
    return 0;
}

/* The node hierarchy: children are nodes of the file, no node is its own ancestor, and no chain
 * of children is deeper than MODEL_MAX_NODE_DEPTH: Assimp's reader recurses down it (a chain of
 * tens of thousands of nodes would exhaust its stack). node[] (n_nodes) holds the nodes' values;
 * work[] (3 n_nodes, zeroed) is work space: each node's height, the next child to visit and the
 * greatest height below it so far, found by a walk down the children with an explicit stack. */
static int check_nodes(layout *l, const uint32_t *node, uint32_t n_nodes, uint32_t *work)
{
    const uint32_t IN_PROGRESS = UINT32_MAX; /* a height while the node is on the stack */
    uint32_t *height = work, *cursor = work + n_nodes, *best = cursor + n_nodes;
    uint32_t stack[MODEL_MAX_NODE_DEPTH];
    for (uint32_t root = 0; root < n_nodes; root++) {
        if (height[root]) continue;
        uint32_t depth = 0;
        if (children_of(l, node, root, &cursor[root])) return -1;
        stack[depth++] = root, height[root] = IN_PROGRESS, best[root] = 1;
        while (depth) {
            uint32_t i = stack[depth - 1], c = cursor[i];
            if (!c) { /* all of i's children seen */
                height[i] = best[i], depth--;
                if (depth && best[stack[depth - 1]] < height[i] + 1) best[stack[depth - 1]] = height[i] + 1;
                continue;
            }
            cursor[i] = l->d.values[c].next;
            uint64_t child;
            if (!json_whole(&l->d, c, &child) || child >= n_nodes)
                return fail(l, c, "node %u has a child that is not one of the file's %u nodes", i, n_nodes);
            if (height[child] == IN_PROGRESS)
                return fail(l, c, "node %u has node %llu for a child, which is its ancestor or itself; a node "
                            "hierarchy is a tree", i, (unsigned long long)child);
            if (height[child]) {
                if (best[i] < height[child] + 1) best[i] = height[child] + 1;
            } else {
                if (depth == MODEL_MAX_NODE_DEPTH)
                    return fail(l, c, "the node hierarchy is deeper than %d levels; sylva reads hierarchies up to "
                                "that", MODEL_MAX_NODE_DEPTH);
                if (children_of(l, node, (uint32_t)child, &cursor[child])) return -1;
                stack[depth++] = (uint32_t)child, height[child] = IN_PROGRESS, best[child] = 1;
            }
            if (best[i] > MODEL_MAX_NODE_DEPTH)
                return fail(l, node[i], "the node hierarchy is deeper than %d levels; sylva reads hierarchies up "
                            "to that", MODEL_MAX_NODE_DEPTH);
        }
    }
    return 0;
}

/* Each animation channel's sampler and target node are the animation's and the file's, and each
 * sampler's output holds a value for each of its input's times (three for a cubic spline):
 * Assimp 5.2 reads one (or three) per time whatever the output's count, and for morph weights
 * divides the count by the times and takes two from the quotient of a cubic spline (an output of
 * fewer than three values a time made it allocate 16 GB a key). */
static int check_animations(layout *l, const uint32_t *accessor, uint32_t n_accessors, uint32_t n_nodes)
{
    uint32_t animations, n_animations;
    if (array(l, "animations", &animations, &n_animations)) return -1;
    char what[64];
    uint32_t v = l->d.values[animations].first;
    for (uint32_t i = 0; i < n_animations; i++, v = l->d.values[v].next) {
        uint32_t samplers = json_member(&l->d, v, "samplers"), channels = json_member(&l->d, v, "channels"), n = 0;
        if ((samplers && l->d.values[samplers].kind != JSON_ARRAY) || (channels && l->d.values[channels].kind != JSON_ARRAY))
            return fail(l, v, "animation %u's samplers or channels are not an array", i);
        for (uint32_t s = samplers ? l->d.values[samplers].first : 0; s; s = l->d.values[s].next, n++) {
            snprintf(what, sizeof what, "animation %u sampler %u", i, n);
            uint32_t input, output;
            uint64_t times, values;
            if (l->d.values[s].kind != JSON_OBJECT) return fail(l, s, "%s is not an object", what);
            if (accessor_ref(l, s, "input", n_accessors, what, &input) ||
                accessor_ref(l, s, "output", n_accessors, what, &output))
                return -1;
            if (input == UINT32_MAX || output == UINT32_MAX) continue;
            if (whole(l, accessor[input], "count", -1, 1, UINT32_MAX, "the accessor", &times) ||
                whole(l, accessor[output], "count", -1, 1, UINT32_MAX, "the accessor", &values))
                return -1;
            int cubic = json_string_is(&l->d, json_member(&l->d, s, "interpolation"), "CUBICSPLINE");
            if (values < (cubic ? 3 : 1) * times)
                return fail(l, s, "%s has %llu times and %llu values; it needs %s for each time", what,
                            (unsigned long long)times, (unsigned long long)values,
                            cubic ? "three (a cubic spline's tangents and value)" : "one");
        }
        uint32_t k = 0;
        for (uint32_t c = channels ? l->d.values[channels].first : 0; c; c = l->d.values[c].next, k++) {
            snprintf(what, sizeof what, "animation %u channel %u", i, k);
            uint64_t sampler, target_node;
            uint32_t target = json_member(&l->d, c, "target");
            if (l->d.values[c].kind != JSON_OBJECT) return fail(l, c, "%s is not an object", what);
            if (!n) return fail(l, c, "%s names a sampler, and its animation has none", what);
            if (whole(l, c, "sampler", -1, 0, n - 1, what, &sampler)) return -1;
            if (!target || l->d.values[target].kind != JSON_OBJECT)
                return fail(l, c, "%s has no target object; a channel names the node it moves", what);
            if (!n_nodes) return fail(l, target, "%s names a node, and the file has none", what);
            if (whole(l, target, "node", -1, 0, n_nodes - 1, what, &target_node)) return -1;
        }
    }
    return 0;
}

int gltf_layout_check(const char *json, size_t n, uint64_t bin, const char *where, err_buf *err)
{
    layout l = {.where = where, .err = err};
    if (json_read(&l.d, json, n, where, err)) return -1;
    int rc = -1;
    uint64_t *held = NULL;     /* owned: freed below; the buffers' bytes, then the views' lengths and strides */
    uint32_t *accessor = NULL; /* owned: freed below; the accessors' values, then the nodes' and work space */
    uint32_t buffers, n_buffers, views, n_views, accessors, n_accessors, nodes, n_nodes;
    if (l.d.values[0].kind != JSON_OBJECT) {
        fail(&l, 0, "a glTF file is one JSON object");
        goto done;
    }
    uint32_t asset = json_member(&l.d, 0, "asset"), version = asset ? json_member(&l.d, asset, "version") : 0;
    if (!version || l.d.values[version].kind != JSON_STRING || l.d.values[version].len < 1 ||
        l.d.text[l.d.values[version].at + 1] != '2') {
        fail(&l, version ? version : asset, "the file states no glTF version 2 (\"asset\": {\"version\": "
             "\"2.0\"}); sylva reads glTF 2.0");
        goto done;
    }
    if (array(&l, "buffers", &buffers, &n_buffers) || array(&l, "bufferViews", &views, &n_views) ||
        array(&l, "accessors", &accessors, &n_accessors) || array(&l, "nodes", &nodes, &n_nodes))
        goto done;
    held = calloc((size_t)n_buffers + 2 * (size_t)n_views + 1, sizeof *held);
    accessor = calloc((size_t)n_accessors + 4 * (size_t)n_nodes + 1, sizeof *accessor);
    if (!held || !accessor) {
        err_nomem(err, "%s: out of memory checking %u buffers, %u buffer views and %u accessors", where, n_buffers,
                  n_views, n_accessors);
        goto done;
    }
    for (uint32_t i = 0, a = l.d.values[accessors].first; i < n_accessors; i++, a = l.d.values[a].next)
        accessor[i] = a;
    uint32_t *node = accessor + n_accessors, *work = node + n_nodes;
    for (uint32_t i = 0, v = l.d.values[nodes].first; i < n_nodes; i++, v = l.d.values[v].next) node[i] = v;
    uint64_t *view_len = held + n_buffers, *view_stride = view_len + n_views;
    if (check_buffers(&l, bin, buffers, n_buffers, held) ||
        check_views(&l, views, n_views, held, n_buffers, view_len, view_stride) ||
        check_accessors(&l, accessor, n_accessors, n_views, view_len, view_stride) ||
        check_primitives(&l, accessor, n_accessors) || check_skins(&l, accessor, n_accessors, node, n_nodes) ||
        check_nodes(&l, node, n_nodes, work) || check_animations(&l, accessor, n_accessors, n_nodes))
        goto done;
    rc = 0;
done:
    free(held);
    free(accessor);
    json_free(&l.d);
    return rc;
}
