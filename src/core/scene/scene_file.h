/* scene_file.h — a scene file, read and validated, before any plugin runs.
 *
 * scene_file_load() parses the YAML (libyaml), checks every key against the host's section
 * schemas (host_schema.h) and every plugin block against that plugin's schema (looked up in the
 * plugin registry by name), fills defaults, resolves relative paths against the scene file's
 * folder and merges included species files. Any problem stops loading with
 * "file:line:column: message" in err.
 *
 * Ownership: a scene_file owns everything reachable from it (one arena); scene_file_free()
 * releases it all. The sylva_params it holds point into that arena and stay valid until then.
 */
#ifndef SYLVA_SCENE_FILE_H
#define SYLVA_SCENE_FILE_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "scene/phenology.h"
#include "util/err.h"
#include "util/name_index.h"

struct plugin_registry;

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

/* A named camera beside the scene's own (the viewpoints: section). */
typedef struct viewpoint {
    const char *name;
    camera_settings camera;
    uint32_t line, column;  /* of its name */
} scene_viewpoint;

typedef struct sun_settings {
    int enabled;
    double direction[3];    /* unit, from the ground toward the sun */
    double azimuth_deg;     /* clockwise from north (+Y) */
    double elevation_deg;
    double irradiance;      /* on a surface facing the sun */
    double color[3];        /* linear RGB tint, multiplied with irradiance */
    double angular_diameter_deg;
    char date_time_utc[32]; /* "2026-06-21T13:30:00Z" when placed by date_time, else "" */
    double latitude_deg, longitude_deg; /* where date_time placed it (site origin or given) */
} sun_settings;

/* Where the scene stands on the Earth (docs/sites.md). Without a `site:` section crs_wkt is
 * NULL and every position is in local metres. With one, local = map - origin: a map point
 * (easting, northing, height) stands at (E - origin[0], N - origin[1], h - origin[2]). */
typedef struct site_settings {
    const char *crs_wkt;    /* the site's projected CRS as WKT, or NULL: local metres only */
    const char *crs_name;   /* its short name for messages (e.g. "WGS 84 / UTM zone 14N"), or NULL */
    double origin[3];       /* map coordinates of the local origin */
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

typedef enum shape_kind {
    SHAPE_MESH = 0,   /* inline vertices + triangles (+ optional uvs) */
    SHAPE_BOX = 1,    /* size[3], centred on the origin */
    SHAPE_SPHERE = 2, /* radius, subdivisions (icosphere) */
    SHAPE_QUAD = 3,   /* size[2] in the XY plane, normal +Z, uvs 0..1 */
    SHAPE_DISK = 4    /* radius, segments, XY plane */
} shape_kind;

typedef struct shape_spec {
    shape_kind kind;
    double size[3];
    double radius;
    uint32_t subdivisions;
    const double *vertices; uint32_t n_vertices; /* xyz triples */
    const double *uvs;      uint32_t n_uvs;      /* uv pairs, n_uvs == n_vertices or 0 */
    const double *triangles; uint32_t n_triangles; /* index triples (validated integers) */
} shape_spec;

typedef struct material_spec {
    const char *name;
    sylva_bsdf bsdf;
    double albedo[3];
    double transmittance[3];
    const char *texture_path; /* absolute, or NULL */
    int alpha_mask;
    uint32_t line, column;
} material_spec;

/* What an object is: a built-in shape, a model file, or a group of parts placed as one. */
typedef enum object_kind { OBJECT_SHAPE = 0, OBJECT_MODEL = 1, OBJECT_GROUP = 2 } object_kind;

/* How an object's height is found (docs/scene-file.md, objects). */
typedef enum object_base {
    OBJECT_AT_Z = 0,          /* position gave z */
    OBJECT_ABOVE_GROUND = 1,  /* origin height_above_ground above the terrain at (x, y) */
    OBJECT_ON_GROUND = 2      /* lowest point on the lowest terrain under the footprint */
} object_base;

typedef struct object_spec {
    const char *name;
    object_kind kind;
    shape_spec shape;         /* OBJECT_SHAPE */
    const char *model_path;   /* OBJECT_MODEL: resolved path */
    double model_scale;       /* OBJECT_MODEL: metres per file unit (after the file's own unit) */
    int model_up;             /* OBJECT_MODEL: a model_up (model_import.h) */
    const char *model_root;   /* OBJECT_MODEL: resolved folder its files must lie in; NULL: the model's */
    uint32_t group;           /* OBJECT_GROUP: index into scene_file.groups */
    double position[3], rotation_deg[3], scale[3];
    double heading_deg;       /* clockwise from north (+Y) about +Z, after rotation */
    object_base base;
    double height_above_ground; /* OBJECT_ABOVE_GROUND */
    int development;          /* 0, or the development it is part of + 1 (scene_file.developments) */
    const char *material;     /* a material name (checked to exist), or NULL for the default */
    const char *file;         /* where it is written: the scene file, or a layout CSV */
    uint32_t line, column;
} object_spec;

/* A group: parts (shapes or models, positioned in the group's frame) placed as one object. */
typedef struct group_spec {
    const char *name;
    object_spec *parts; uint32_t n_parts;
    uint32_t line, column;
} group_spec;

typedef struct species_spec {
    const char *name;
    const char *plugin;       /* tree plugin name, or NULL when `shape` gives the prototype */
    const sylva_params *params; /* the plugin's block (NULL for shapes) */
    shape_spec shape;
    const char *material;     /* shapes: material name or NULL */
    uint32_t variants;        /* age variants to build */
    const sylva_params *ecology; /* the block under the ecology plugin's species_section, or NULL */
    phenology phenology;      /* its leaf habit and days (evergreen when not given) */
    uint32_t line, column;
} species_spec;

typedef struct plant_spec {
    uint32_t species;         /* index into scene_file.species */
    double position[3];
    int snap_to_terrain;      /* 1 when the position gave no z (two numbers) or a height above ground */
    double above_ground;      /* with snap_to_terrain: metres above the terrain (0 for [x, y]) */
    double rotation_deg;      /* about +Z */
    double scale;
    double age;               /* (0, 1] */
    int development;          /* 1: new planting, part of the development */
    uint32_t line, column;
} plant_spec;

typedef enum terrain_source { TERRAIN_NONE = 0, TERRAIN_GRID = 1, TERRAIN_PLUGIN = 2 } terrain_source;

typedef struct terrain_spec {
    terrain_source source;
    const char *plugin;         /* TERRAIN_PLUGIN */
    const sylva_params *params; /* TERRAIN_PLUGIN */
    const double *grid; uint32_t nx, ny; /* TERRAIN_GRID: ny rows of nx heights, row 0 = south */
    double origin[2], spacing[2];
    const char *material;       /* material name or NULL for the default ground */
    uint32_t line, column;
} terrain_spec;

typedef struct ecology_spec {
    const char *plugin;         /* NULL: no ecology */
    const sylva_params *params;
    uint32_t line, column;
} ecology_spec;

/* The most developments one scene may name: a visibility map's bit mask of the developments
 * seen from a cell is exact in a 32-bit float band. */
#define SCENE_MAX_DEVELOPMENTS 24u

/* One target of a visibility map given by hand (ztv: targets:). */
typedef struct ztv_target_spec {
    double position[3];       /* local metres; position[2] is the height when has_height */
    int has_height;           /* 0: the target stands above_ground metres above the terrain */
    double above_ground;
    uint32_t development;     /* index into scene_file.developments */
    uint32_t line, column;
} ztv_target_spec;

/* The ztv: section: how `sylva ztv` maps where the development can be seen from (docs/ztv.md).
 * The targets are the explicit ones when given, else points target_heights above each
 * development object's footprint when given, else `samples` points on each development
 * object's surface. */
typedef struct ztv_settings {
    double observer_height;   /* metres above the terrain */
    double radius;            /* metres from the nearest target; INFINITY: the whole terrain */
    double cell;              /* metres; 0: the terrain's own grid */
    int screening;            /* 0 none (bare earth), 1 vegetation, 2 all (a ztv_mode) */
    uint32_t samples;
    const double *target_heights; uint32_t n_target_heights;
    ztv_target_spec *targets; uint32_t n_targets;
    uint32_t line, column;    /* of the section (of the file's start when absent) */
} ztv_settings;

/* The photo: section: the photograph a photomontage puts the development into, and how its
 * camera is matched (`sylva montage`, docs/photomontage.md). */
typedef struct photo_settings {
    const char *file;           /* resolved path, or NULL: no photo: section */
    const char *control_points; /* resolved path, or NULL: the scene's camera as it is */
    double sensor_width_mm;     /* 0: from the photograph's EXIF */
    double focal_length_mm;     /* 0: from the photograph's EXIF, else the camera's field of view */
    int fit_position;           /* 1: the match may move the camera */
    int fit_focal_length;       /* 1: the match may change the focal length */
    int fit_distortion;         /* 1: the match fits the radial distortion k1 */
    int camera_from_exif;       /* 1: start the match at the photograph's GPS position and direction */
    double exposure;            /* the rendered development's gain against the photograph */
    uint32_t line, column;
} photo_settings;

typedef struct scene_file {
    const char *path;           /* as given */
    const char *dir;            /* absolute folder of the file */
    const char **includes; uint32_t n_includes; /* the species files `include:` read, as
                                                   canonical paths, in the order read */
    site_settings site;
    image_settings image;
    camera_settings camera;
    int has_camera;             /* 0: the file has no camera: section (SCENE_FILE_NO_CAMERA, for a
                                   command that draws nothing); camera is then all zeros and the
                                   terrain is refined around no eye (its footprint's centre) */
    scene_viewpoint *viewpoints; uint32_t n_viewpoints; /* the named views, in file order */
    sun_settings sun;
    sky_settings sky;
    earth_settings earth;
    ground_cover_settings ground_cover;
    snow_settings snow;         /* snow on the ground (off by default) */
    season_settings season;     /* the day of the year the plants are shown on */
    terrain_spec terrain;
    species_spec *species; uint32_t n_species;
    plant_spec *plants; uint32_t n_plants;
    const char *plants_file;    /* plants: {file: F}: a saved ecology run (resolved), or NULL */
    uint32_t plants_file_line, plants_file_column;
    ecology_spec ecology;
    group_spec *groups; uint32_t n_groups;
    object_spec *objects; uint32_t n_objects; /* layouts expanded: one per CSV row */
    const char **developments; uint32_t n_developments; /* names, in order of first mention */
    ztv_settings ztv;
    photo_settings photo;
    material_spec *materials; uint32_t n_materials;
    name_index material_names;  /* name → index into materials; owned (its table) */
    name_index species_names;   /* name → index into species; owned (its table) */
    struct arena *arena;        /* owns all of the above but the two indexes' tables */
} scene_file;

/* Reads and validates `path`. plugins may be NULL only for scenes that name no plugin.
 * Returns a new scene_file (caller frees with scene_file_free) or NULL with err set. */
scene_file *scene_file_load(const char *path, const struct plugin_registry *plugins, err_buf *err);

/* Flags of scene_file_load_with. */
#define SCENE_FILE_NO_CAMERA 1u /* the camera: section may be left out: for a command that draws no
                                   picture (ztv, probe) */
/* scene_file_load with flags (0: as scene_file_load). */
scene_file *scene_file_load_with(const char *path, const struct plugin_registry *plugins, unsigned flags,
                                 err_buf *err);
void scene_file_free(scene_file *sf); /* accepts NULL */

/* Makes the viewpoint named `name` the scene's camera (before the scene is built). Returns 0, or
 * -1 with err (ERR_USAGE) naming the viewpoints there are. */
int scene_file_use_viewpoint(scene_file *sf, const char *name, err_buf *err);

/* Shows the plants on the day text names (a season's name or a date YYYY-MM-DD, as the season:
 * key takes) instead of the scene's own season (before the scene is built). Returns 0, or -1
 * with err (ERR_USAGE) saying what would be valid. */
int scene_file_use_season(scene_file *sf, const char *text, err_buf *err);

/* Index of a material or species by name, or -1 (a hash lookup). */
int scene_file_material_index(const scene_file *sf, const char *name);
int scene_file_species_index(const scene_file *sf, const char *name);

#endif
