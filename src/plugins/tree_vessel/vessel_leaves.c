/* vessel_leaves.c — the five leaf distributions of 004 §3.3.2: a layout in the branch's local
 * frame, then each leaf placed on a terminal branch. */
#include "vessel_leaves.h"

/* A slot at `along` whose outward direction is turned about the axis by `turn` radians from
 * local +x and leans `lean` radians from the axis (pi/2: perpendicular). */
static vessel_leaf_slot slot(double along, double turn, double lean)
{
    vessel_vec out = vv(cos(turn) * sin(lean), cos(lean), sin(turn) * sin(lean));
    vessel_vec across = vv_madd(vv(0, 1, 0), out, -out.y);
    if (vv_len(across) < 1e-9) across = vv(1, 0, 0); /* a leaf along the branch */
    return (vessel_leaf_slot){.along = along, .out = vv_unit(out), .across = vv_unit(across)};
}

uint32_t vessel_leaf_layout(const vessel_params *p, vessel_leaf_slot *slots)
{
    uint32_t n = p->leaf_density, k = 0;
    const double side = M_PI / 2;
    if (n & 1u) slots[k++] = slot(1.0, 0, 0); /* the odd leaf on the tip, along the branch */
    uint32_t m = n - (n & 1u);
    switch (p->leaf_type) {
    case VESSEL_LEAF_STACKED:
        for (uint32_t i = 0; i < m / 2; i++) {
            double along = (i + 1.0) / (m / 2 + 1.0), twist = i * VESSEL_LEAF_TWIST * VESSEL_DEG;
            slots[k++] = slot(along, twist, side);
            slots[k++] = slot(along, M_PI + twist, side);
        }
        break;
    case VESSEL_LEAF_STAGGERED:
    case VESSEL_LEAF_CONIFEROUS: {
        double lean = p->leaf_type == VESSEL_LEAF_CONIFEROUS ? VESSEL_CONIFEROUS_ANGLE * VESSEL_DEG : side;
        for (uint32_t i = 0; i < m; i++)
            slots[k++] = slot((i + 1.0) / (m + 1.0), ((i & 1u) ? M_PI : 0) + (i / 2) * VESSEL_LEAF_TWIST * VESSEL_DEG,
                              lean);
        break;
    }
    case VESSEL_LEAF_SPIRAL:
        for (uint32_t i = 0; i < m; i++)
            slots[k++] = slot((i + 1.0) / (m + 1.0), i * p->phyllotaxis * VESSEL_DEG, side);
        break;
    case VESSEL_LEAF_BUNCHED:
    default:
        for (uint32_t i = 0; i < m; i++) slots[k++] = slot(1.0, 2 * M_PI * i / m, side);
        break;
    }
    return k;
}

double vessel_leaf_side(const vessel_branch *b, const vessel_params *p)
{
    return VESSEL_LEAF_SIDE_PER_SIZE * p->leaf_size * sqrt((double)b->vessels);
}

vessel_leaf vessel_leaf_on(const vessel_branch *b, const vessel_leaf_slot *s, double side)
{
    return (vessel_leaf){.base = vv_madd(b->base, b->frame.c[1], s->along * b->length),
                         .out = frame_to_tree(&b->frame, s->out),
                         .across = frame_to_tree(&b->frame, s->across), .size = side};
}

uint32_t vessel_leaves_place(const vessel_branch *b, const vessel_params *p, vessel_leaf *out)
{
    vessel_leaf_slot slots[VESSEL_MAX_LEAF_DENSITY];
    uint32_t n = vessel_leaf_layout(p, slots);
    double side = vessel_leaf_side(b, p);
    for (uint32_t k = 0; k < n; k++) out[k] = vessel_leaf_on(b, &slots[k], side);
    return n;
}
