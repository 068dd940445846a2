/* scene_settings.h — the settings a scene carries and the back ends read: the image, the camera,
 * the sun and the sky, the Earth under a site, the site itself, snow and ground cover. The scene
 * file's reader fills them (scene_file/scene_file.h) and the scene copies them (scene.h); the
 * back ends (render/, pov/, geometry/, ztv/, montage/) take them from here, never from the file.
 *
 * Plain values; nothing here allocates (a site's strings are owned by whoever holds it).
 */
#ifndef SYLVA_SCENE_SETTINGS_H
#define SYLVA_SCENE_SETTINGS_H

#include <stdint.h>

/* The curve that maps exposed linear light to PNG values (render/tone_curve.h). */
typedef enum tone_curve { TONE_AGX = 0, TONE_ACES = 1 } tone_curve;

typedef struct image_settings {
    uint32_t width, height; /* pixels */
    uint32_t spp;           /* samples per pixel (the most, with noise_target) */
    double noise_target;    /* relative standard error at which a pixel stops sampling; 0: off */
    uint64_t seed;
    uint32_t max_depth;     /* path vertices after the camera */
    double exposure;        /* stops applied before tone mapping (PNG only), when exposure_set */
    int exposure_set;       /* 0: the exposure is metered from the rendered image */
    tone_curve tone;
    double crown_proxy;     /* plants below this projected height (px) show a crown proxy; 0: never */
} image_settings;

/* A height given above the terrain, resolved once the terrain exists (scene_build.c). */
typedef struct ground_height {
    int given;              /* 1: the height is `above` the terrain; 0: it was given directly */
    double above;           /* metres above the terrain */
    uint32_t line, column;  /* where it was given, for messages */
} ground_height;

typedef struct camera_settings {
    double position[3];     /* position[2] is NaN in a scene_file while eye_ground applies */
    ground_height eye_ground;     /* the eye's height above the terrain, when given */
    ground_height look_at_ground; /* look_at's height above the terrain (look_at[2] NaN), when given */
    int has_look_at;        /* 1: look_at given; 0: direction given (or default) */
    double look_at[3];
    double direction[3];    /* unit after loading; with a height above ground, final once the
                               scene is built (scene_build.c) */
    double up[3];
    double roll_deg;        /* turn about the view, clockwise seen from behind (camera_frame.h) */
    int cylindrical;        /* 0: a pinhole (perspective); 1: a cylindrical panorama (render/camera.h) */
    double k1, k2;          /* radial lens distortion (geometry/camera_project.h); 0 but in a
                               photomontage's matched camera */
    double fov_deg;         /* horizontal field of view; derived from focal length when given */
    double focal_length_mm; /* 0 when fov was given */
    double sensor_width_mm;
    double f_number;        /* thin lens (render/lens.h); 0: a pinhole, everything sharp */
    double focus_distance;  /* metres to the surface in sharp focus, with f_number */
    double vignette;        /* strength of the cos^4 falloff, 0 to 1 */
} camera_settings;

typedef struct sun_settings {
    int enabled;
    double direction[3];    /* unit, from the ground toward the sun */
    double azimuth_deg;     /* clockwise from north (+Y) */
    double elevation_deg;
    double irradiance;      /* on a surface facing the sun */
    double color[3];        /* linear RGB tint, multiplied with irradiance */
    double angular_diameter_deg;
    char date_time_utc[32]; /* "2026-06-21T13:30:00Z" when placed by date_time, else "" */
    char date_time_local[48]; /* date_time as given, the local time with its UTC offset
                               * ("2026-06-21T14:30:00+01:00"), else "" */
    double latitude_deg, longitude_deg; /* where date_time placed it (site origin or given) */
} sun_settings;

/* Where the scene stands on the Earth (docs/sites.md). Without a `site:` section crs_wkt is
 * NULL and every position is in local metres. With one, local = map - origin: a map point
 * (easting, northing, height) stands at (E - origin[0], N - origin[1], h - origin[2]). */
typedef struct site_settings {
    const char *crs_wkt;    /* the site's projected CRS as WKT, or NULL: local metres only */
    const char *crs_name;   /* its short name for messages (e.g. "WGS 84 / UTM zone 14N"), or NULL */
    double origin[3];       /* map coordinates of the local origin */
    double latitude_deg;    /* degrees north (WGS 84) of the origin; meaningful with crs_wkt only */
} site_settings;

/* The Earth under a site (docs/models/curvature.md): camera rays bend so that a point at
 * horizontal distance d from the camera appears lower by (1 - refraction) d^2 / (2 radius). */
typedef struct earth_settings {
    int curvature;          /* 1: camera rays follow the curved path; 0: straight (a flat Earth) */
    double refraction;      /* refraction coefficient k (0.13 is the usual daytime value) */
    double radius;          /* metres */
} earth_settings;

/* Grass and herbs near the camera (geometry/ground_cover_place.h, docs/rendering.md). */
typedef struct ground_cover_settings {
    int enabled;            /* 1: place ground cover for the camera being rendered */
    double density;         /* tufts per square metre of full meadow */
    double radius;          /* metres: the farthest tuft (0: where a blade shrinks to a pixel) */
    uint32_t max_instances; /* the count is capped here (the radius shrinks to fit) */
} ground_cover_settings;

/* Snow lying on the ground (docs/seasons.md#snow): the procedural ground turns to snow where
 * it lies (geometry/ground_cover.h), and no grass stands there. Off unless the scene has a
 * snow: section. */
typedef struct snow_settings {
    int on;                 /* 1: the scene has a snow: section */
    double cover;           /* share of the open ground the snow covers, 0..1 (1: all of it) */
    double min_height;      /* metres, local frame: snow lies only above it (-HUGE_VAL: everywhere) */
} snow_settings;

typedef enum sky_model { SKY_NONE = 0, SKY_CONSTANT = 1, SKY_PREETHAM = 2, SKY_PHYSICAL = 3 } sky_model;

typedef struct sky_settings {
    sky_model model;
    double turbidity;       /* Preetham */
    double visibility_km;   /* SKY_PHYSICAL: meteorological range at the camera */
    double density;         /* SKY_PHYSICAL: factor on the air's and the haze's density */
    double scale;           /* multiplies the sky radiance */
    double color[3];        /* SKY_CONSTANT radiance */
    double ground_albedo;   /* below the horizon the sky shows this times the horizon-average */
    double ambient[3];      /* verification mode's constant ambient term (and POV-Ray's) */
} sky_settings;

#endif
