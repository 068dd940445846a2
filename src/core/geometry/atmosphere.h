/* atmosphere.h — the physical sky and aerial perspective: single scattering of sunlight by air
 * molecules (Rayleigh) and haze (Mie) in an atmosphere whose densities fall exponentially with
 * altitude over a spherical Earth (Nishita et al. 1993, with the constants of Bruneton and
 * Neyret 2008). One model gives the sky seen from the observer and the extinction and
 * in-scattered light along any straight segment, so that distant terrain fades toward the
 * horizon sky. See docs/models/atmosphere.md for the equations and every deviation.
 *
 * Units: lengths in metres, altitudes above sea level; radiance in sylva's unit (a sun
 * irradiance of 1 is about 100 klx, docs/rendering.md "Light"). The sun's irradiance given to
 * atmosphere_init is the one at the observer (the ground); the model divides it by the sun's
 * transmittance there to get the irradiance at the top of the atmosphere.
 *
 * Colour: three channels, the linear sRGB primaries, each computed at one wavelength
 * (680, 550 and 440 nm). Directions are unit vectors in sylva's frame (Z up).
 *
 * Ownership: an atmosphere is a plain value (its tables are arrays inside it); no allocation.
 */
#ifndef SYLVA_ATMOSPHERE_H
#define SYLVA_ATMOSPHERE_H

/* The sun's column densities toward the sun, tabulated by altitude and the cosine of the sun's
 * zenith angle there (for the sky, over the sphere). */
#define ATMO_DEPTH_ALTITUDES 48
#define ATMO_DEPTH_COSINES 96
/* The multiple-scattering term, tabulated by altitude and the sun's cosine there. */
#define ATMO_MS_ALTITUDES 32
#define ATMO_MS_COSINES 32
/* The sky seen from the observer, by elevation and azimuth from the sun's. */
#define ATMO_VIEW_ELEVATIONS 129
#define ATMO_VIEW_AZIMUTHS 129
/* The sun's transmittance and the multiple-scattering term by altitude along the scene's (flat)
 * vertical (for segments). */
#define ATMO_SUN_ALTITUDES 256

typedef struct atmosphere {
    double beta_rayleigh[3];  /* Rayleigh scattering = extinction at sea level, 1/m */
    double beta_mie_ext;      /* Mie extinction at sea level, 1/m (grey) */
    double beta_mie_sca;      /* Mie scattering at sea level, 1/m */
    double scale_rayleigh;    /* scale heights, m */
    double scale_mie;
    double mie_g;             /* Cornette-Shanks asymmetry */
    double r_ground, r_top;   /* radii of sea level and of the top of the atmosphere, m */
    double altitude;          /* the observer's altitude, m */
    double sun_dir[3];        /* unit, toward the sun */
    double sun_top[3];        /* sun irradiance at the top of the atmosphere */
    double sun_ground[3];     /* sun irradiance at the observer, as given */
    double light_scale;       /* factor on scattered light (sky.scale) */
    double ground_albedo;     /* of the sphere below the horizon */
    double sky_irradiance[3]; /* the sky's irradiance on level ground at the observer; lights
                                 the ground below the horizon */
    /* Column densities (Rayleigh, Mie; metres of sea-level air) from altitude a (row) toward a
     * direction of cosine mu from the local vertical (column) to the top of the atmosphere;
     * negative where the ray meets the ground. Rows: a = ATMO_ALT_MIN + (top - ATMO_ALT_MIN) u^2,
     * u in [0, 1]; columns: mu = w^3, w in [-1, 1] uniformly (fine near the horizon). */
    float depth[ATMO_DEPTH_ALTITUDES][ATMO_DEPTH_COSINES][2];
    /* Multiple scattering (Hillaire 2020, eq. 10): the isotropic radiance Psi_ms per unit
     * top-of-atmosphere sun irradiance that scattering of every order above the first leaves at
     * a point, by altitude (u^2 rows as above) and the sun's cosine mu_s in [-1, 1] (uniform). */
    float multiple[ATMO_MS_ALTITUDES][ATMO_MS_COSINES][3];
    /* Sun transmittance (RGB) and Psi_ms at altitude a along the flat frame, a from ATMO_ALT_MIN
     * to the top with the same u^2 spacing. */
    float sun_flat[ATMO_SUN_ALTITUDES][3];
    float multiple_flat[ATMO_SUN_ALTITUDES][3];
    /* The sky's radiance from the observer (what atmosphere_sky returns, interpolated): rows
     * elevation 90 deg x |x| with x in [-1, 1] uniformly (a row exactly at the horizon, dense
     * near it), columns the azimuth from the sun's, 0 to 180 deg uniformly (the sky is symmetric
     * about the sun's vertical plane). */
    float view[ATMO_VIEW_ELEVATIONS][ATMO_VIEW_AZIMUTHS][3];
    double sun_east[2];       /* unit horizontal direction of the sun ((1, 0) when overhead) */
} atmosphere;

/* Lowest altitude the tables hold (m); below it they hold their value there. */
#define ATMO_ALT_MIN (-500.0)

/* Sets up the model. visibility_km is the meteorological range at the observer's altitude
 * (Koschmieder: total extinction at 550 nm = 3.912 / V); density multiplies the densities of
 * both kinds of scatterer after that (0: no atmosphere). sun_dir need not be unit. Returns 0,
 * or -1 when the visibility is longer than clean air allows at that altitude (Rayleigh
 * scattering alone), an argument is out of range or the sun has no light left at the observer;
 * on -1 *a is unspecified. The tables are built on up to `threads` threads (0: one per
 * processor), each row by one thread, so they are the same for any count. */
int atmosphere_init(atmosphere *a, const double sun_dir[3], const double sun_irradiance[3], double altitude,
                    double visibility_km, double density, double light_scale, double ground_albedo, unsigned threads);
/* The longest visibility (km) clean air gives at this altitude: 3.912 / Rayleigh(550 nm). */
double atmosphere_clear_visibility_km(double altitude);

/* Radiance of the sky seen from the observer toward unit dir: the light scattered into the
 * view by the air up to the top of the atmosphere, or up to the ground sphere below the horizon
 * plus the ground's reflection through that air (bilinear in the view table, which holds the
 * integral at its nodes). */
void atmosphere_sky(const atmosphere *a, const double dir[3], double rgb[3]);

/* Extinction and in-scattering along a straight segment of the scene's flat frame from a point
 * at altitude alt0 along unit dir for length metres: what reaches the segment's start is
 * transmittance * (light leaving its end) + inscatter. Deterministic quadrature. */
void atmosphere_segment(const atmosphere *a, double alt0, const double dir[3], double length,
                        double transmittance[3], double inscatter[3]);

/* Sun transmittance at altitude alt in the flat frame (the table by altitude). */
void atmosphere_sun_transmittance(const atmosphere *a, double alt, double t[3]);

/* Total extinction (1/m) at 550 nm at altitude alt: Koschmieder's beta there. */
double atmosphere_extinction_550(const atmosphere *a, double alt);

#endif
