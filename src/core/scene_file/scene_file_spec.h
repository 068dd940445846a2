/* scene_file_spec.h — what a scene file says, once read and validated: its sections as specs
 * (shapes, materials, objects, groups, species, plants, trees, terrain, ecology, ztv, photo,
 * study) and the settings the scene copies (scene/scene_settings.h), gathered in the scene_file
 * record that scene_file_load() returns (scene_file.h).
 *
 * Ownership: a scene_file owns everything reachable from it (one arena); scene_file_free()
 * releases it all. The sylva_params it holds point into that arena and stay valid until then.
 */
#ifndef SYLVA_SCENE_FILE_SPEC_H
#define SYLVA_SCENE_FILE_SPEC_H

#include <stdint.h>

#include "sylva/plugin.h"
#include "season/phenology.h"
#include "scene/scene_settings.h"
#include "site/canopy_read.h"
#include "site/landcover_source.h"
#include "util/err.h"
#include "util/name_index.h"

/* A named camera beside the scene's own (the viewpoints: section). */
typedef struct viewpoint {
    const char *name;
    camera_settings camera;
    const char *file;       /* where it is written: NULL for the scene file, else a study's points file */
    uint32_t line, column;  /* of its name (of its row in a points file; 0 for a point OGR read) */
} scene_viewpoint;

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

/* One tree of a survey (the trees: section): a plant of its species whose model is scaled to the
 * measured height (docs/trees.md). */
typedef struct tree_spec {
    uint32_t species;         /* index into scene_file.species */
    double position[2];       /* local metres; the tree stands on the terrain */
    double height;            /* measured, metres (> 0) */
    double crown;             /* crown diameter, metres; 0: not measured */
    double age;               /* normalised age in (0, 1] from the surveyed years; 0: not given */
    double rotation_deg;      /* about +Z: the golden angle times its index, so neighbours differ */
    const char *feature;      /* "FID 12", "line 5" */
} tree_spec;

typedef struct trees_spec {
    tree_spec *trees; uint32_t n_trees;
    const char *file;         /* the survey's name as written */
    int development;          /* 1: a new planting, part of the development */
    uint32_t line, column;    /* of the file key */
} trees_spec;

/* What a feature of a planting plan is (the planting: section, docs/mitigation.md). */
typedef enum planting_kind {
    PLANTING_BLOCK = 0,   /* a polygon planted on a grid: a woodland block */
    PLANTING_BELT,        /* rows along a line: a hedgerow, shelter or screening belt */
    PLANTING_TREE,        /* one tree at a point */
    PLANTING_FELLING,     /* a polygon whose existing vegetation is removed */
    PLANTING_KINDS
} planting_kind;

#define PLANTING_MAX_SPECIES 8u

/* The nursery stock a feature is planted as (host_stock_sizes order): the young plant's form
 * (scene_build/planting_stock.h). */
typedef enum planting_stock_form {
    STOCK_WHIP = 0,       /* a single unbranched stem, 0.6-0.9 m */
    STOCK_FEATHERED,      /* a leader with side shoots down most of its height, 1.8-2.4 m */
    STOCK_STANDARD        /* a clear stem of 1.8 m under a small crown, 2.5-3 m */
} planting_stock_form;

/* One feature of a planting plan, as drawn: inline in the scene file or a feature of a vector
 * file. Coordinates are local metres (turned from map coordinates when the plan gives those). */
typedef struct planting_feature {
    planting_kind kind;
    const char *name;           /* its name, else "blocks[2]" or the file's "FID 7" */
    double (*xy)[2]; uint32_t n_xy; /* polygon ring (not closed), line, or the tree's point */
    uint32_t species[PLANTING_MAX_SPECIES]; /* blocks: the mix; belts: the sequence along a row */
    double share[PLANTING_MAX_SPECIES];     /* blocks: each species' share, summing to 1 */
    uint32_t n_species;
    double spacing;             /* metres between plants: a block's grid, a belt's row */
    uint32_t rows;              /* belts: rows side by side */
    double row_spacing;         /* belts: metres between rows */
    double stock_height[2];     /* the nursery stock's range of heights at planting, metres */
    planting_stock_form stock;  /* its form: the size given, else the one of the height given */
    const char *file;           /* where it is written: the scene file or the vector file */
    uint32_t line, column;      /* in the scene file (of the file key for a file's feature) */
} planting_feature;

/* A planting plan (the planting: section): what is planted and felled, when, and the rule the
 * plants grow by. */
typedef struct planting_spec {
    planting_feature *features; uint32_t n_features;
    uint32_t n_plants_drawn;    /* blocks, belts and trees (felling aside) */
    double year;                /* the calendar year of planting, as stated */
    int map_coordinates;        /* 1: written in the site's CRS (local = map - origin), 0: local metres */
    uint64_t seed;              /* places the plants: the same plants in the same places every year */
    double full_grown_age;      /* years: a species' full-grown variant stands at this age */
    double thinning_year;       /* years since planting from which blocks and belts are thinned; 0: never */
    double thinning_keep;       /* the share of a block's or belt's plants kept by thinning */
    int ecology;                /* 1: blocks' and belts' plants compete and die by the scene's ecology */
    int age_existing;           /* 1: the scene's ecology is grown on through the plan's years */
    uint32_t maintenance_years; /* years since planting during which dead plants are replaced in kind */
    uint32_t line, column;      /* of the section */
} planting_spec;

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
    int given;                /* 1: the scene has a ztv: section (a study then maps it) */
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

/* What a study renders from each viewpoint (`sylva study`, docs/study.md): the view without the
 * development, with it, the development's outline over the view without it, and the sheet that
 * sets the three out with the viewpoint's facts and a location map (sheet/sheet.h). */
typedef enum study_product {
    STUDY_EXISTING = 0, STUDY_PROPOSED = 1, STUDY_WIRELINE = 2, STUDY_SHEET = 3
} study_product;
#define STUDY_PRODUCTS 4u /* the products of each viewpoint */
/* The study's own product, made once for every viewpoint: its visibility map (docs/study.md, "The
 * ZTV"), named `ztv` after the products of each viewpoint. */
#define STUDY_ZTV STUDY_PRODUCTS
/* The frames a study renders each product in: a 50 mm lens on a full-frame sensor, a 53.5 degree
 * planar view and a 90 degree cylindrical panorama (study/study_frames.h). */
typedef enum study_frame { STUDY_SINGLE = 0, STUDY_PLANAR_53 = 1, STUDY_CYLINDRICAL_90 = 2 } study_frame;
#define STUDY_FRAMES 3u

/* A year a study is made at: years since planting and the season's day (docs/mitigation.md). */
typedef struct study_year {
    double years;
    uint32_t day;               /* day of the year (season/phenology.h) */
    const char *season;         /* as written: "winter", "2027-06-21" */
} study_year;

#define STUDY_MAX_YEARS 16u

/* The study: section: which viewpoints, products and frames `sylva study` renders, and at what
 * size (docs/study.md). */
typedef struct study_settings {
    const char **viewpoints;    /* names of the scene's viewpoints, in rank order; NULL: all of them */
    uint32_t n_viewpoints;
    scene_viewpoint *points;    /* the viewpoints of the points file, in its order */
    uint32_t n_points;
    const char *points_file;    /* resolved, or NULL */
    const char *points_layer;   /* the points file's layer (OGR), or NULL: its only one */
    double eye_height;          /* metres above the ground for a point that gives none */
    unsigned products;          /* bits 1u << study_product */
    unsigned frames;            /* bits 1u << study_frame */
    uint32_t size[2];           /* pixels of every frame; 0, 0: a width from print_width and dpi, or
                                   the image's width, and the frame's own height for it */
    double print_width_mm;      /* 0: no print size */
    double dpi;                 /* pixels per inch of the print */
    uint32_t spp;               /* 0: the image's */
    int inner_edges;            /* 1: the wireline draws inner edges inside the silhouette */
    study_year *years;          /* with a planting plan: the years the study is made at (study_years.c) */
    uint32_t n_years;
    uint32_t line, column;      /* of the section (of the file's start when absent) */
} study_settings;

#define COMMUNITY_MAX_SPECIES 16u

/* A plant community of the landcover: section: the plants of one kind or class of ground,
 * placed at a density with heights spread over a range (docs/landcover.md, Communities). */
typedef struct landcover_community {
    int kind;                   /* a land_kind, or -1: the class `code` */
    int64_t code;
    uint32_t species[COMMUNITY_MAX_SPECIES]; /* scene species indices */
    double share[COMMUNITY_MAX_SPECIES];     /* each one's share, summing to 1 */
    uint32_t n_species;
    double density;             /* plants per hectare */
    double height[2];           /* lowest and tallest, metres */
    uint32_t line, column;      /* of the entry */
} landcover_community;

/* The landcover: section: the site's land-cover map (docs/landcover.md). */
typedef struct landcover_spec {
    int given;                  /* 0: no landcover: section */
    landcover_source source;    /* its path, strings and classes in the scene_file's arena */
    uint32_t line, column;      /* of the map's key (raster: or polygons:) */
    landcover_community *communities; /* in the arena */
    uint32_t n_communities;
    int has_plant_area;
    double plant_area[4];       /* west, south, east, north: map coordinates */
    double plant_spacing;       /* metres between the nodes the map is read on for planting */
    double plant_edge;          /* metres: the band inside a community's edge where it thins out */
} landcover_spec;

/* The canopy: section: the site's canopy heights (docs/canopy.md). */
typedef struct canopy_spec {
    int given;                  /* 0: no canopy: section */
    canopy_source source;       /* its paths in the scene_file's arena */
    uint32_t line, column;      /* of the key naming the heights (chm: or dsm:) */
    uint32_t dtm_line, dtm_column; /* of dtm: (with dsm:) */
    int fit_plants;             /* 1: the ecology's plants are fitted to the heights */
} canopy_spec;

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
    trees_spec trees;           /* the trees: section (n_trees 0 without one) */
    planting_spec planting;     /* the planting: section (n_features 0 without one) */
    ecology_spec ecology;
    group_spec *groups; uint32_t n_groups;
    object_spec *objects; uint32_t n_objects; /* layouts expanded: one per CSV row */
    const char **developments; uint32_t n_developments; /* names, in order of first mention */
    ztv_settings ztv;
    photo_settings photo;
    study_settings study;
    landcover_spec landcover;
    canopy_spec canopy;
    material_spec *materials; uint32_t n_materials;
    name_index material_names;  /* name → index into materials; owned (its table) */
    name_index species_names;   /* name → index into species; owned (its table) */
    uint64_t digest;            /* of what every render of the scene reads but the camera: the file's
                                   sections but camera:, viewpoints: and study:, the files it includes
                                   and its layouts (scene_file_digest.c) */
    struct arena *arena;        /* owns all of the above but the two indexes' tables */
} scene_file;

#endif
