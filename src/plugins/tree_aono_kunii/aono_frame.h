/* aono_frame.h — the dynamic frame x', y', z' of a mother branch P_a P_b and the child tips in
 * it (seed 000, equations (16)–(19)).
 *
 * z' runs along the mother branch, y' is horizontal, x' completes the frame. The paper's
 * frame is left-handed and its transform (18) carries the misprint T23 = cos β cos α; here the
 * frame is built from the mother direction and the horizontal and is orthonormal by
 * construction: y' = normalise(ẑ × z'), x' = z' × y'. In sylva's right-handed coordinates that
 * triple is the mirror image (y → −y) of the paper's right-turning one, so a tree appears as the
 * paper draws it. A vertical mother (S = 0 in (19)) is the paper's special case: y' is the
 * horizontal tangent of the circle through P_b about the z axis, x' points toward the axis, and
 * on the axis itself x' = +y, y' = +x (α = β = 90°, mirrored).
 */
#ifndef AONO_FRAME_H
#define AONO_FRAME_H

typedef struct aono_frame {
    double x[3], y[3], z[3]; /* unit axes x', y', z' in world coordinates */
} aono_frame;

/* The frame of the mother branch pa -> pb. Returns 0, or -1 when pa and pb coincide (the
 * branch has no direction); the frame is then left unchanged. */
int aono_frame_build(const double pa[3], const double pb[3], aono_frame *f);

/* The tip of a child of length rho at angle phi from z' whose plane through z' makes the angle
 * azimuth with x' (δ for the first child, δ + γ for the second), both in degrees (16)–(17):
 *   P = P_b + rho (sin φ cos az x' + sin φ sin az y' + cos φ z'). */
void aono_frame_child(const aono_frame *f, const double pb[3], double rho, double phi_deg,
                      double azimuth_deg, double out[3]);

#endif
