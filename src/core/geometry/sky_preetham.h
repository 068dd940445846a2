/* sky_preetham.h — the Preetham et al. (1999) analytic daylight sky ("A Practical Analytic Model
 * for Daylight"): radiance toward any direction for a sun direction and turbidity.
 *
 * Units: Preetham's luminance Y is in kcd/m^2; sylva's radiance unit is chosen so that a sun
 * irradiance of 1 corresponds to 100 klx, so sky radiance = Y / 100 * scale, converted from
 * Yxy through CIE XYZ to linear sRGB (Rec. 709 primaries, D65). Directions are unit vectors in
 * sylva's frame (Z up). Below the horizon the model is not defined: the sky returns a ground
 * colour (ground_albedo times the horizon-average radiance).
 */
#ifndef SYLVA_SKY_PREETHAM_H
#define SYLVA_SKY_PREETHAM_H

#include <stdint.h>

typedef struct sky_preetham {
    double sun_dir[3];     /* unit, toward the sun; elevation clamped to >= 0 */
    double turbidity;      /* 1.7 .. 10 */
    double scale;
    double theta_s;        /* sun zenith angle */
    double zenith_Yxy[3];  /* Y (kcd/m^2), x, y at the zenith */
    double perez_Y[5], perez_x[5], perez_y[5]; /* A..E for Y, x, y */
    double denom_Y, denom_x, denom_y;          /* Perez F(0, theta_s) */
    double ground_rgb[3];
} sky_preetham;

/* Sets up the model. sun_dir need not be above the horizon (elevation is clamped to 0 for the
 * sky's own formulae) nor of unit length. Returns 0, or -1 for a turbidity outside [1.7, 10],
 * a zero or non-finite sun_dir, a negative or non-finite scale, or ground_albedo outside
 * [0, 1]; on -1 *s is untouched. */
int sky_preetham_init(sky_preetham *s, const double sun_dir[3], double turbidity, double scale,
                      double ground_albedo);
/* Linear sRGB radiance toward unit direction dir (from the viewer into the sky). */
void sky_preetham_radiance(const sky_preetham *s, const double dir[3], double rgb[3]);
/* Zenith luminance Y_z (kcd/m^2) and chromaticity x_z, y_z, Preetham eqs. in appendix A.2;
 * theta_s is clamped to [0, pi/2]. */
void sky_preetham_zenith(double turbidity, double theta_s, double Yxy[3]);
/* Perez et al. luminance distribution F(theta, gamma) with coefficients c[5] (A..E);
 * cos(theta) is clamped to >= 1e-3 so the horizon stays finite. */
double sky_perez(const double c[5], double theta, double gamma);

#endif
