/* host_schema.c — the tables behind every host section of a scene file.
 *
 * Conventions: lengths in metres, angles in degrees, colours as linear RGB. Optional keys whose
 * absence matters (camera look_at, sun direction, ...) carry a default that the loader ignores
 * unless the key is set; their help says so.
 */
#include "scene_file/host_schema.h"

#include <stddef.h>
#include <string.h>

#include "scene/land_cover.h"
#include "site/landcover_legend.h"

#define COUNT(a) ((uint32_t)(sizeof(a) / sizeof((a)[0])))
#define MIN SYLVA_PARAM_HAS_MIN
#define MAX SYLVA_PARAM_HAS_MAX
#define MIN_X (SYLVA_PARAM_HAS_MIN | SYLVA_PARAM_MIN_EXCLUSIVE)
#define MAX_X (SYLVA_PARAM_HAS_MAX | SYLVA_PARAM_MAX_EXCLUSIVE)
#define REQ SYLVA_PARAM_REQUIRED

const char *const host_sections[] = {"image",   "site",    "camera",  "sun",     "sky",     "materials",
                                     "terrain", "species", "plants",  "ecology", "groups",  "objects",
                                     "earth",   "viewpoints", "ztv",     "photo",   "ground_cover", "season",  "snow",
                                     "landcover", "trees", "canopy", "study", "planting", NULL};

const char *const host_shape_names[] = {"mesh", "box", "sphere", "quad", "disk", NULL};
const char *const host_sky_models[] = {"none", "constant", "preetham", "physical", NULL};
const char *const host_material_types[] = {"lambert", "leaf", NULL};
static const char *const host_tone_curves[] = {"agx", "aces", NULL};

static const double zero3[3] = {0, 0, 0}, one3[3] = {1, 1, 1}, half3[3] = {0.5, 0.5, 0.5};
static const double north[3] = {0, 1, 0}, z_up[3] = {0, 0, 1};
static const double ambient_default[3] = {0.2, 0.2, 0.2};
static const double sky_blue[3] = {0.5, 0.7, 1.0};
static const double zero2[2] = {0, 0}, one2[2] = {1, 1};

/* --- image ---------------------------------------------------------------------------------- */
static const sylva_param_spec image_params[] = {
    {.name = "width",
     .type = SYLVA_P_INT,
     .flags = MIN | MAX,
     .def = 640,
     .min = 1,
     .max = HOST_IMAGE_MAX_SIZE,
     .unit = "px",
     .help = "Image width in pixels."},
    {.name = "height",
     .type = SYLVA_P_INT,
     .flags = MIN | MAX,
     .def = 360,
     .min = 1,
     .max = HOST_IMAGE_MAX_SIZE,
     .unit = "px",
     .help = "Image height in pixels."},
    {.name = "spp",
     .type = SYLVA_P_INT,
     .flags = MIN | MAX,
     .def = 16,
     .min = 1,
     .max = 1048576,
     .unit = "samples",
     .help = "Samples per pixel (the most, with noise_target); stratified, so noise falls as one over "
             "its square root or faster."},
    {.name = "seed",
     .type = SYLVA_P_INT,
     .flags = MIN | MAX,
     .def = 0,
     .min = 0,
     .max = 9007199254740992.0,
     .help = "Scene seed: every random stream (pixels, plants, plugins) is derived from it."},
    {.name = "max_depth",
     .type = SYLVA_P_INT,
     .flags = MIN | MAX,
     .def = 6,
     .min = 1,
     .max = 1024,
     .unit = "bounces",
     .help =
         "Longest light path in surface interactions after the camera; 1 is direct light only."},
    {.name = "exposure",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0,
     .min = -20,
     .max = 20,
     .unit = "stops",
     .help = "Exposure applied before tone mapping to PNG (not to EXR); default: metered from the "
             "rendered image, its mean log luminance on mid-grey (auto-exposure)."},
    {.name = "tone",
     .type = SYLVA_P_ENUM,
     .def_str = "agx",
     .choices = host_tone_curves,
     .help = "Tone curve for PNG: agx (log encoding and a sigmoid; bright colours go to white) or "
             "aces (the Narkowicz 2015 ACES fit)."},
    {.name = "crown_proxy",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 24,
     .min = 0,
     .max = 100000,
     .unit = "px",
     .help = "Plants drawn smaller than this height in pixels show camera rays a calibrated crown envelope "
             "instead of their leaves (a smooth distant forest); 0: always the full plants."},
    {.name = "noise_target",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0,
     .min = 0,
     .max = 1,
     .help = "Adaptive sampling: a pixel stops taking samples, at 16, 32, 64, ... up to spp, once the "
             "standard error of its luminance is at most this share of its mean; 0: every pixel "
             "takes spp samples."},
};
const host_schema host_schema_image = {"image", "Output size, sampling and the scene seed.",
                                       image_params, COUNT(image_params)};

/* --- site ----------------------------------------------------------------------------------- */
static const sylva_param_spec site_params[] = {
    {.name = "crs", .type = SYLVA_P_STRING,
     .help = "The site's projected CRS in metres, as EPSG:NNNN or WKT; default: the DTM's CRS (the "
             "UTM zone of its centre when the DTM is in degrees)."},
    {.name = "origin", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 3, .def_list = zero2,
     .def_len = 2, .unit = "m",
     .help = "Map coordinates [E, N] or [E, N, h] of the local origin; default: the DTM "
             "footprint's centre rounded to whole metres, at height 0."},
};
const host_schema host_schema_site = {
    "site", "Where the scene stands on the Earth: its CRS and the origin of the local frame.",
    site_params, COUNT(site_params)};

/* --- positions in map coordinates ------------------------------------------------------------ */
static const sylva_param_spec position_params[] = {
    {.name = "easting", .type = SYLVA_P_REAL, .unit = "m",
     .help = "Easting in the site CRS (with northing)."},
    {.name = "northing", .type = SYLVA_P_REAL, .unit = "m",
     .help = "Northing in the site CRS (with easting)."},
    {.name = "longitude", .type = SYLVA_P_REAL, .flags = MIN | MAX, .min = -180, .max = 180,
     .unit = "deg", .help = "WGS 84 longitude, east positive (with latitude)."},
    {.name = "latitude", .type = SYLVA_P_REAL, .flags = MIN | MAX, .min = -90, .max = 90,
     .unit = "deg", .help = "WGS 84 latitude, north positive (with longitude)."},
    {.name = "height", .type = SYLVA_P_REAL, .unit = "m",
     .help = "Height in the site's vertical datum (the DTM's heights)."},
    {.name = "height_above_ground", .type = SYLVA_P_REAL, .unit = "m",
     .help = "Height above the terrain under the point, instead of height."},
};
const host_schema host_schema_position = {
    "position in map coordinates",
    "A point given as {easting, northing} or {longitude, latitude}, with a height or a height "
    "above ground (needs site:).",
    position_params, COUNT(position_params)};

static const char *const camera_projections[] = {"perspective", "cylindrical", NULL};

/* --- camera --------------------------------------------------------------------------------- */
static const sylva_param_spec camera_params[] = {
    {.name = "position", .type = SYLVA_P_LIST, .flags = REQ, .min_len = 2, .max_len = 3, .unit = "m",
     .help = "Position of the camera's eye point: [x, y, z], [x, y] with height_above_ground, or "
             "a map position."},
    {.name = "height_above_ground", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 1.6, .min = 0,
     .max = 100000, .unit = "m",
     .help = "Eye height above the terrain under the position (1.5 to 1.7 is a standing eye)."},
    {.name = "look_at", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 3, .def_list = zero3,
     .def_len = 3, .unit = "m",
     .help = "A point the camera looks at (give look_at or direction, not both); [x, y] is on the "
             "ground."},
    {.name = "direction", .type = SYLVA_P_VEC3, .def_list = north, .def_len = 3,
     .help = "Viewing direction, any length but not zero (used when look_at is absent)."},
    {.name = "up", .type = SYLVA_P_VEC3, .def_list = z_up, .def_len = 3,
     .help = "Up direction of the image; must not be parallel to the viewing direction."},
    {.name = "fov", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 60, .min = 0, .max = 360,
     .unit = "deg",
     .help = "Horizontal field of view (give fov or focal_length, not both); under 180 for a "
             "perspective camera."},
    {.name = "projection", .type = SYLVA_P_ENUM, .def_str = "perspective", .choices = camera_projections,
     .help = "perspective (a pinhole, as a photograph) or cylindrical (a panorama: angle across "
             "linear in x, the tangent of the elevation linear in y)."},
    {.name = "focal_length", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 35, .min = 0,
     .max = 100000, .unit = "mm",
     .help = "Lens focal length; when given, the field of view follows from it and sensor_width."},
    {.name = "sensor_width", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 36, .min = 0,
     .max = 1000, .unit = "mm", .help = "Sensor width, used with focal_length (36 is full frame)."},
    {.name = "heading", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -360, .max = 360,
     .unit = "deg",
     .help = "Compass direction of the view, clockwise from north (+Y), instead of look_at."},
    {.name = "pitch", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -90, .max = 90,
     .unit = "deg", .help = "Angle of the view above the horizon (negative looks down), with heading."},
    {.name = "roll", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -180, .max = 180,
     .unit = "deg",
     .help = "Turn of the camera about its view, clockwise as seen from behind it."},
    {.name = "f_number", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1000,
     .help = "Lens f-number for depth of field (a thin lens, its pupil focal_length / f_number "
             "wide; give focus_distance with it); 0 is a pinhole, everything sharp."},
    {.name = "focus_distance", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 10, .min = 0,
     .max = 1e7, .unit = "m",
     .help = "Distance from the camera to what is in sharp focus, along the view (with f_number)."},
    {.name = "vignette", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1,
     .help = "Strength of the lens's natural falloff toward the corners: brightness times "
             "1 - s + s cos^4 of the angle off the axis; 0 is none."},
};
const host_schema host_schema_camera = {
    "camera", "A pinhole camera: where it stands, where it looks and how wide it sees.",
    camera_params, COUNT(camera_params)};

/* --- sun ------------------------------------------------------------------------------------ */
static const sylva_param_spec sun_params[] = {
    {.name = "enabled",
     .type = SYLVA_P_BOOL,
     .def = 1,
     .help = "Whether the sun lights the scene (the sky still uses its position)."},
    {.name = "azimuth",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 180,
     .min = -360,
     .max = 360,
     .unit = "deg",
     .help = "Compass direction of the sun, clockwise from north (+Y); 90 is east."},
    {.name = "elevation",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 45,
     .min = -90,
     .max = 90,
     .unit = "deg",
     .help = "Angle of the sun above the horizon."},
    {.name = "direction",
     .type = SYLVA_P_VEC3,
     .help = "Direction from the ground toward the sun, instead of azimuth and elevation."},
    {.name = "date_time",
     .type = SYLVA_P_STRING,
     .help = "Place the sun for this instant, ISO 8601 with its UTC offset "
             "(\"2026-06-21T14:30:00+01:00\" or ...Z), instead of azimuth and elevation."},
    {.name = "latitude",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0,
     .min = -90,
     .max = 90,
     .unit = "deg",
     .help = "Where the sun is seen from with date_time, north positive; only without a site "
             "(which uses its origin)."},
    {.name = "longitude",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0,
     .min = -180,
     .max = 180,
     .unit = "deg",
     .help = "Where the sun is seen from with date_time, east positive; only without a site "
             "(which uses its origin)."},
    {.name = "irradiance",
     .type = SYLVA_P_REAL,
     .flags = MIN,
     .def = 1,
     .min = 0,
     .help = "Irradiance on a surface facing the sun, in sylva's unit (1 is about 100 klx)."},
    {.name = "color",
     .type = SYLVA_P_VEC3,
     .flags = MIN,
     .min = 0,
     .def_list = one3,
     .def_len = 3,
     .help = "Linear RGB tint multiplied with the irradiance."},
    {.name = "angular_diameter",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0.53,
     .min = 0,
     .max = 20,
     .unit = "deg",
     .help = "Apparent diameter of the sun's disc; sets shadow softness."},
};
const host_schema host_schema_sun = {"sun", "The sun: a directional light with an angular size.",
                                     sun_params, COUNT(sun_params)};

/* --- sky ------------------------------------------------------------------------------------ */
static const sylva_param_spec sky_params[] = {
    {.name = "model", .type = SYLVA_P_ENUM, .def_str = "preetham", .choices = host_sky_models,
     .help = "Sky radiance: preetham (analytic daylight), physical (scattering in the air, with "
             "aerial perspective), constant (one colour) or none (black)."},
    {.name = "turbidity", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 3, .min = 1.7,
     .max = 10, .help = "Haze of the preetham sky: 2 is very clear, 10 is hazy."},
    {.name = "visibility", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 30, .min = 0, .max = 1000,
     .unit = "km",
     .help = "Meteorological range at the camera of the physical sky: 30-40 is a temperate summer "
             "day, 10 is hazy, 100 or more very clear."},
    {.name = "density", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 1, .min = 0, .max = 100,
     .help = "Factor on the density of the physical sky's air and haze (0: no atmosphere)."},
    {.name = "scale", .type = SYLVA_P_REAL, .flags = MIN, .def = 1, .min = 0,
     .help = "Factor on the sky's radiance."},
    {.name = "color", .type = SYLVA_P_VEC3, .flags = MIN, .min = 0, .def_list = sky_blue,
     .def_len = 3, .help = "Linear RGB radiance of the constant sky (model: constant only)."},
    {.name = "ground_albedo", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0.2, .min = 0,
     .max = 1, .help = "Reflectance of the ground seen below the horizon."},
    {.name = "ambient", .type = SYLVA_P_VEC3, .flags = MIN, .min = 0, .def_list = ambient_default,
     .def_len = 3,
     .help = "Constant ambient light of the verification mode and the POV-Ray export."},
};
const host_schema host_schema_sky = {"sky", "The sky dome that lights the scene from every side.",
                                     sky_params, COUNT(sky_params)};

/* --- earth ---------------------------------------------------------------------------------- */
static const sylva_param_spec earth_params[] = {
    {.name = "curvature", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Bend camera rays for the Earth's curvature (default: on with a site, else off)."},
    {.name = "refraction", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0.13, .min = -2,
     .max = 2, .help = "Atmospheric refraction coefficient k; objects drop by (1 - k) d^2 / 2R."},
    {.name = "radius", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 6371000, .min = 1000,
     .max = 1e9, .unit = "m", .help = "Radius R of the Earth (the mean radius by default)."},
};
const host_schema host_schema_earth = {
    "earth", "The Earth's curvature and the atmosphere's refraction over long views.",
    earth_params, COUNT(earth_params)};

/* --- snow ----------------------------------------------------------------------------------- */
static const sylva_param_spec snow_params[] = {
    {.name = "cover", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 1, .min = 0, .max = 1,
     .help = "Share of the open ground under snow: 1 a closed cover, less leaves patches of ground bare."},
    {.name = "min_height", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -12000, .max = 9000,
     .unit = "m", .help = "Snow lies only above this map height, as the terrain's altitudes (default: at every height)."},
};
const host_schema host_schema_snow = {
    "snow", "Snow lying on the terrain's procedural ground (docs/seasons.md).", snow_params,
    COUNT(snow_params)};

/* --- ground_cover ---------------------------------------------------------------------------- */
static const sylva_param_spec ground_cover_params[] = {
    {.name = "enabled", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Place grass and herbs on the ground near the camera being rendered."},
    {.name = "density", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 24, .min = 0, .max = 400,
     .unit = "1/m^2", .help = "Tufts per square metre of full meadow; other ground takes its share."},
    {.name = "radius", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 5000, .unit = "m",
     .help = "Farthest tuft from the camera (0: where a blade shrinks to about a pixel)."},
    {.name = "max_instances", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 200000, .min = 0, .max = 5000000,
     .help = "At most this many tufts; the radius shrinks until the count fits."},
};
const host_schema host_schema_ground_cover = {
    "ground_cover", "Grass and herbs near the camera, placed by the ground's cover.",
    ground_cover_params, COUNT(ground_cover_params)};

/* --- ztv ----------------------------------------------------------------------------------- */
static const char *const ztv_screenings[] = {"none", "vegetation", "all", "canopy", NULL};
static const sylva_param_spec ztv_params[] = {
    {.name = "observer_height", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 2, .min = 0,
     .max = 10000, .unit = "m", .help = "Eye height of the observer above the ground of each cell."},
    {.name = "radius", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1e7, .unit = "m",
     .help = "Map the cells within this distance of the nearest target (0: the whole terrain)."},
    {.name = "cell", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1e6, .unit = "m",
     .help = "Cell size of the map (0: the terrain's own grid, a cell per node)."},
    {.name = "screening", .type = SYLVA_P_ENUM, .def_str = "all", .choices = ztv_screenings,
     .help = "What screens the view besides bare earth: none, vegetation (the plants), all (plants "
             "and objects) or canopy (the surface of the canopy: section's heights); bare earth is always "
             "mapped too."},
    {.name = "samples", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 32, .min = 1, .max = 65535,
     .help = "Targets sampled on each development object's surface (when neither targets nor "
             "target_heights are given)."},
    {.name = "target_heights", .type = SYLVA_P_LIST, .max_len = 64, .unit = "m",
     .help = "Targets at these heights above each development object's base as placed (e.g. a "
             "turbine's hub and blade tip: [150, 270])."},
    {.name = "targets", .type = SYLVA_P_LIST, .help = "Targets given by hand: a list of "
     "{position, height_above_ground, development}."},
};
const host_schema host_schema_ztv = {
    "ztv", "The visibility map (sylva ztv): where the development can be seen from.", ztv_params,
    COUNT(ztv_params)};

static const sylva_param_spec ztv_target_params[] = {
    {.name = "position", .type = SYLVA_P_LIST, .flags = REQ, .min_len = 2, .max_len = 3, .unit = "m",
     .help = "[x, y, z], [x, y] with height_above_ground, or a map position."},
    {.name = "height_above_ground", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -10000,
     .max = 100000, .unit = "m", .help = "Height of the target above the terrain (a hub height)."},
    {.name = "development", .type = SYLVA_P_STRING,
     .help = "The development the target belongs to (default: the scene's only one, or "
             "'development')."},
};
const host_schema host_schema_ztv_target = {
    "ztv targets item", "One target of the visibility map.", ztv_target_params,
    COUNT(ztv_target_params)};

/* --- photo --------------------------------------------------------------------------------- */
static const sylva_param_spec photo_params[] = {
    {.name = "file", .type = SYLVA_P_PATH, .flags = REQ,
     .help = "The photograph (JPEG, PNG or TIFF) the development is rendered into."},
    {.name = "control_points", .type = SYLVA_P_PATH,
     .help = "Control points (CSV u,v,easting,northing,height or x,y,z; or ImGRAFT's text) the "
             "camera is matched to; without them the scene's camera is used as it is."},
    {.name = "sensor_width", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1000, .unit = "mm",
     .help = "Width of the photograph on the sensor (0: from its EXIF)."},
    {.name = "focal_length", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 100000, .unit = "mm",
     .help = "Focal length the photograph was taken with (0: from its EXIF)."},
    {.name = "fit_position", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Let the match move the camera (needs points at several distances; default: the "
             "camera's position is surveyed)."},
    {.name = "fit_focal_length", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Let the match change the focal length."},
    {.name = "fit_distortion", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Fit the lens's radial distortion k1 (and render with it)."},
    {.name = "camera_from_exif", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Start the camera match at the photograph's GPS position and altitude and its GPS "
             "direction (EXIF) instead of the scene camera's (needs a site: section)."},
    {.name = "exposure", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 1, .min = 0, .max = 1e6,
     .help = "Gain on the rendered development against the photograph's linear values."},
};
const host_schema host_schema_photo = {"photo", "The photograph of a photomontage (sylva montage).", photo_params,
                                       COUNT(photo_params)};

/* --- study -------------------------------------------------------------------------------- */
const char *const host_study_products[] = {"existing", "proposed", "wireline", "sheet", "ztv", NULL};
const char *const host_study_frames[] = {"single", "planar_53", "cylindrical_90", NULL};
static const double no_size[2] = {0, 0};
static const sylva_param_spec study_params[] = {
    {.name = "viewpoints", .type = SYLVA_P_STRING,
     .help = "The scene's viewpoints to render, in rank order: a list of names, or names separated by "
             "spaces or commas (default: every one, in the file's order)."},
    {.name = "points", .type = SYLVA_P_PATH,
     .help = "More viewpoints from a file of points: a CSV (id or name; easting and northing, x and y, or "
             "longitude and latitude; height_above_ground; heading) or a point layer OGR reads (GeoPackage, "
             "Shapefile, GeoJSON) with the fields name, height_above_ground and heading."},
    {.name = "points_layer", .type = SYLVA_P_STRING,
     .help = "The layer of the points file holding the viewpoints (default: its only one)."},
    {.name = "eye_height", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 1.5, .min = 0, .max = 10000, .unit = "m",
     .help = "Eye height above the ground of a point that gives no height_above_ground."},
    {.name = "products", .type = SYLVA_P_STRING, .def_str = "existing proposed wireline",
     .help = "What each viewpoint gives: existing (the view without the development), proposed (with it), "
             "wireline (the development's outline over the existing view), sheet (the three on one page with "
             "the viewpoint's facts and a location map, PDF and PNG); and once for the study, ztv (its "
             "visibility map, made anyway when the scene has a ztv: section); a list or names separated by "
             "spaces or commas."},
    {.name = "frames", .type = SYLVA_P_STRING, .def_str = "single",
     .help = "The frames of each product: single (50 mm on a full-frame sensor, 39.6 x 27 degrees), planar_53 "
             "(53.5 x 18.2 degrees, planar), cylindrical_90 (a 90 degree cylindrical panorama); a list or "
             "names separated by spaces or commas."},
    {.name = "size", .type = SYLVA_P_LIST, .flags = MIN | MAX, .min = 0, .max = HOST_IMAGE_MAX_SIZE, .min_len = 2,
     .max_len = 2, .def_list = no_size, .def_len = 2, .unit = "px",
     .help = "[width, height] of every frame in pixels, or [width, 0] for each frame's own height (default: a "
             "width from print_width and dpi, else the image's width, and each frame's own height for it)."},
    {.name = "print_width", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 10000, .unit = "mm",
     .help = "Width of the printed frame: the frame is print_width / 25.4 * dpi pixels wide, and the "
             "sheet's page is as wide, in A-series proportions (0: no print size; the sheet A3 landscape, "
             "420)."},
    {.name = "dpi", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 300, .min = 0, .max = 10000,
     .help = "Pixels per inch of the print (with print_width) and of the sheet's page and pictures."},
    {.name = "spp", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 0, .min = 0, .max = 1 << 20,
     .help = "Samples per pixel (0: the image's spp)."},
    {.name = "inner_edges", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Whether the wireline draws the development's inner edges (yellow) inside its outline (red, the "
             "silhouette); false: the outline alone, as for a lattice tower seen as one shape."},
    {.name = "years", .type = SYLVA_P_STRING,
     .help = "With a planting: section, the years since planting the study is made at, each with its season: "
             "\"1 winter, 15 summer\" (the default), each into DIR/year_N_SEASON."},
};
const host_schema host_schema_study = {
    "study", "The viewpoints, products and frames `sylva study` renders from one build of the scene.",
    study_params, COUNT(study_params)};

/* --- landcover ------------------------------------------------------------------------------ */
static const sylva_param_spec landcover_class_params[] = {
    {.name = "code", .type = SYLVA_P_INT, .flags = REQ | MIN | MAX, .min = -2147483647.0, .max = 2147483647.0,
     .help = "The map's code of the class (a text class field's names are numbered 1, 2, ... "
             "alphabetically)."},
    {.name = "name", .type = SYLVA_P_STRING, .help = "The class's name (default: the legend's)."},
    {.name = "kind", .type = SYLVA_P_ENUM, .def_str = "unknown", .choices = land_kind_names,
     .help = "What the ground of the class is (default: the legend's kind, else unknown)."},
};
static const double no_plant_area[4] = {0, 0, 0, 0}; /* unset: the whole terrain */
static const sylva_param_spec landcover_community_params[] = {
    {.name = "kind", .type = SYLVA_P_ENUM, .def_str = "unknown", .choices = land_kind_names,
     .help = "The kind of ground the community grows on (forest holds every forest_* kind, wetland "
             "both wetland_* kinds); or give code."},
    {.name = "code", .type = SYLVA_P_INT, .flags = MIN | MAX, .min = -2147483647.0, .max = 2147483647.0,
     .help = "The map's code of the class the community grows on (in place of kind)."},
    {.name = "species", .type = SYLVA_P_STRING, .flags = REQ,
     .help = "The scene's species of the community, separated by spaces or commas."},
    {.name = "shares", .type = SYLVA_P_LIST, .flags = MIN_X | MAX, .min = 0, .max = 1e6, .max_len = COMMUNITY_MAX_SPECIES,
     .help = "Each species' share of the plants, in the order of species (default: equal shares)."},
    {.name = "density", .type = SYLVA_P_REAL, .flags = REQ | MIN_X | MAX, .min = 0, .max = 100000, .unit = "1/ha",
     .help = "Plants per hectare of the community's ground."},
    {.name = "height", .type = SYLVA_P_LIST, .flags = REQ | MIN_X | MAX, .min = 0, .max = 200, .min_len = 2,
     .max_len = 2, .unit = "m",
     .help = "[lowest, tallest] plant height, metres: heights are spread evenly between them."},
};
static const sylva_param_spec landcover_params[] = {
    {.name = "raster", .type = SYLVA_P_PATH,
     .help = "A classified raster GDAL reads (a code per cell), in any CRS."},
    {.name = "polygons", .type = SYLVA_P_PATH,
     .help = "Polygons OGR reads (GeoPackage, Shapefile, GeoJSON), classed by class_field."},
    {.name = "layer", .type = SYLVA_P_STRING, .help = "The polygons' layer (default: the file's first)."},
    {.name = "class_field", .type = SYLVA_P_STRING,
     .help = "The polygons' attribute holding the class: a code, or a class name."},
    {.name = "legend", .type = SYLVA_P_ENUM, .def_str = "auto", .choices = landcover_legend_choices,
     .help = "What the codes mean: auto, nlcd2011, corine, or names (the class names the map carries)."},
    {.name = "classes", .type = SYLVA_P_GROUP_LIST, .max_len = LAND_COVER_MAX_CLASSES,
     .group = landcover_class_params, .n_group = COUNT(landcover_class_params),
     .help = "Classes that replace or extend the legend's: a list of {code, name, kind}."},
    {.name = "communities", .type = SYLVA_P_GROUP_LIST, .max_len = LAND_COVER_MAX_CLASSES,
     .group = landcover_community_params, .n_group = COUNT(landcover_community_params),
     .help = "The plants of each kind or class of ground: {kind or code, species, shares, density, height}."},
    {.name = "plant_area", .type = SYLVA_P_LIST, .min_len = 4, .max_len = 4, .def_list = no_plant_area, .def_len = 4,
     .unit = "m",
     .help = "[west, south, east, north] map coordinates of the area the communities are planted in "
             "(default: the whole terrain)."},
    {.name = "plant_spacing", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 5, .min = 0.5, .max = 1000, .unit = "m",
     .help = "The grid the map is read on for planting: a cell whose four nodes share a community is planted, "
             "so plants keep this far from a class boundary at most."},
    {.name = "plant_edge", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 10, .min = 0, .max = 1000, .unit = "m",
     .help = "The band inside a community's edge over which it thins out to none, its line wandering by noise "
             "(0: a hard edge)."},
};
const host_schema host_schema_landcover = {
    "landcover", "The site's land-cover map: a class per node of the ground as surveyed.", landcover_params,
    COUNT(landcover_params)};

/* --- canopy --------------------------------------------------------------------------------- */
static const sylva_param_spec canopy_params[] = {
    {.name = "chm", .type = SYLVA_P_PATH,
     .help = "A canopy height model GDAL reads: the vegetation's height above the ground, in any CRS."},
    {.name = "dsm", .type = SYLVA_P_PATH,
     .help = "A surface model (elevations of the canopy's top), read with dtm: the heights are dsm - dtm."},
    {.name = "dtm", .type = SYLVA_P_PATH,
     .help = "The bare-earth elevations of the survey under dsm."},
    {.name = "fit_plants", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Fit the woodland's plants (communities and ecology) to the canopy: each that reaches it scaled to "
             "its height there, those where it is below 0.5 m removed."},
};
const host_schema host_schema_canopy = {
    "canopy", "The site's canopy heights: the vegetation's top above each node of the ground as surveyed.",
    canopy_params, COUNT(canopy_params)};

/* --- materials ------------------------------------------------------------------------------ */
static const sylva_param_spec material_params[] = {
    {.name = "type", .type = SYLVA_P_ENUM, .def_str = "lambert", .choices = host_material_types,
     .help = "lambert: opaque diffuse; leaf: two-sided, reflects and transmits diffusely."},
    {.name = "albedo", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .min = 0, .max = 1,
     .def_list = half3, .def_len = 3,
     .help = "Linear RGB diffuse reflectance, multiplied by the texture when there is one."},
    {.name = "transmittance", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .min = 0, .max = 1,
     .def_list = zero3, .def_len = 3,
     .help = "Linear RGB diffuse transmittance (type: leaf only); albedo plus it is at most 1."},
    {.name = "texture", .type = SYLVA_P_PATH,
     .help = "Image file (PNG, JPEG, EXR, ...) whose colour multiplies the albedo."},
    {.name = "alpha_mask", .type = SYLVA_P_BOOL, .def = 0,
     .help = "Cut the surface away where the texture's alpha is below 0.5 (needs a texture)."},
};
const host_schema host_schema_material = {"materials entry",
                                          "A named surface that terrain, shapes and objects use.",
                                          material_params, COUNT(material_params)};

/* --- terrain -------------------------------------------------------------------------------- */
static const sylva_param_spec terrain_params[] = {
    {.name = "plugin", .type = SYLVA_P_STRING,
     .help = "Terrain plugin that builds the heightfield; its parameters sit beside this key."},
    {.name = "material", .type = SYLVA_P_STRING,
     .help = "Material of the ground (a name from materials:); the default is a grey lambert."},
    {.name = "grid", .type = SYLVA_P_GRID, .unit = "m",
     .help = "Inline heights, rows from south to north, columns from west to east (>= 2 x 2)."},
    {.name = "origin", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 2, .def_list = zero2,
     .def_len = 2, .unit = "m",
     .help = "x and y of the grid's first node (row 0, column 0), or a map position."},
    {.name = "spacing", .type = SYLVA_P_LIST, .flags = MIN_X, .min = 0, .min_len = 2,
     .max_len = 2, .def_list = one2, .def_len = 2, .unit = "m",
     .help = "Distance between grid nodes along x and along y."},
};
const host_schema host_schema_terrain = {
    "terrain", "The ground: an inline height grid or a terrain plugin's block.", terrain_params,
    COUNT(terrain_params)};

/* --- species -------------------------------------------------------------------------------- */
static const double autumn_brown[3] = {0.3, 0.14, 0.03}, fresh_green[3] = {0.2, 0.34, 0.06};
static const double blossom_white[3] = {0.85, 0.7, 0.74}, blossom_faded[3] = {0.62, 0.55, 0.45};
static const sylva_param_spec blossom_params[] = {
    {.name = "first_day", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 100, .min = 1, .max = 366, .unit = "day",
     .help = "Day of the year the first flowers open."},
    {.name = "last_day", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 120, .min = 1, .max = 366, .unit = "day",
     .help = "Day of the year the last flowers fade (before first_day: flowering over new year)."},
    {.name = "color", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .def_list = blossom_white, .def_len = 3, .min = 0,
     .max = 1, .help = "Albedo (linear RGB) of a flower that has just opened."},
    {.name = "faded_color", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .def_list = blossom_faded, .def_len = 3,
     .min = 0, .max = 1, .help = "Albedo (linear RGB) a flower fades to by the end of its life."},
    {.name = "size", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0.02, .min = 0.001, .max = 2, .unit = "m",
     .help = "Width of an open flower, or of the cluster of flowers one disc stands for."},
    {.name = "per_point", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0.3, .min = 0, .max = 1000,
     .help = "Flowers per crown point (leaf of the summer crown) over the whole season."},
    {.name = "max_per_plant", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 1500, .min = 0, .max = 100000,
     .help = "At most this many flowers on one plant over the season."},
};
const host_schema host_schema_blossom = {
    "blossom", "When and how a species flowers (docs/seasons.md).", blossom_params, COUNT(blossom_params)};

static const char *const leaf_habits[] = {"evergreen", "deciduous", NULL}; /* leaf_habit order */
static const sylva_param_spec phenology_params[] = {
    {.name = "habit", .type = SYLVA_P_ENUM, .def_str = "evergreen", .choices = leaf_habits,
     .help = "evergreen (in leaf all year) or deciduous (leaf-off outside leaf_out to leaf_fall)."},
    {.name = "leaf_out", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 120, .min = 1, .max = 366,
     .help = "Day of the year a deciduous species comes into leaf."},
    {.name = "leaf_fall", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 305, .min = 1, .max = 366,
     .help = "Day of the year a deciduous species has shed its leaves (leaf-off from this day)."},
    {.name = "colouring", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 270, .min = 1, .max = 366,
     .help = "Day of the year a deciduous species' leaves start to turn toward autumn_color."},
    {.name = "autumn_color", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .def_list = autumn_brown, .def_len = 3, .min = 0,
     .max = 1, .help = "Leaf albedo (linear RGB) a deciduous species reaches at leaf_fall."},
    {.name = "fresh_color", .type = SYLVA_P_VEC3, .flags = MIN | MAX, .def_list = fresh_green, .def_len = 3, .min = 0,
     .max = 1, .help = "Albedo (linear RGB) of a deciduous species' new leaves at leaf_out."},
    {.name = "fresh_days", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 21, .min = 0, .max = 120, .unit = "day",
     .help = "Days after leaf_out the new leaves take to reach their summer colour (0: no fresh green)."},
    {.name = "blossom", .type = SYLVA_P_GROUP, .group = blossom_params, .n_group = COUNT(blossom_params),
     .help = "The species' flowers: days, colours, size and number (none when not given)."},
};
const host_schema host_schema_phenology = {
    "phenology", "When a species carries its leaves (docs/seasons.md).", phenology_params,
    COUNT(phenology_params)};

static const sylva_param_spec species_params[] = {
    {.name = "plugin", .type = SYLVA_P_STRING,
     .help = "Tree plugin that builds the model; its parameters sit beside this key."},
    {.name = "variants", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 4, .min = 1, .max = 64,
     .help = "Number of age variants of the model to build (plugin species)."},
    {.name = "shape", .type = SYLVA_P_ENUM, .def_str = "box", .choices = host_shape_names,
     .help = "A built-in prototype instead of a plugin (a species gives plugin or shape)."},
    {.name = "material", .type = SYLVA_P_STRING,
     .help = "Material of a built-in shape (a name from materials:)."},
    {.name = "phenology", .type = SYLVA_P_GROUP, .group = phenology_params, .n_group = COUNT(phenology_params),
     .help = "Leaf habit and leaf days of the species (evergreen when not given)."},
};
const host_schema host_schema_species = {
    "species entry", "One kind of plant: a tree plugin's block or a built-in shape.",
    species_params, COUNT(species_params)};

/* --- plants --------------------------------------------------------------------------------- */
static const sylva_param_spec plant_params[] = {
    {.name = "species",
     .type = SYLVA_P_STRING,
     .flags = REQ,
     .help = "Name of a species defined under species:."},
    {.name = "position",
     .type = SYLVA_P_LIST,
     .flags = REQ,
     .min_len = 2,
     .max_len = 3,
     .unit = "m",
     .help = "[x, y, z], or [x, y] to stand on the terrain, or a map position."},
    {.name = "rotation",
     .type = SYLVA_P_REAL,
     .flags = MIN | MAX,
     .def = 0,
     .min = -360,
     .max = 360,
     .unit = "deg",
     .help = "Turn about the vertical axis, counter-clockwise seen from above."},
    {.name = "scale",
     .type = SYLVA_P_REAL,
     .flags = MIN_X,
     .def = 1,
     .min = 0,
     .help = "Uniform size factor on the species' model."},
    {.name = "age",
     .type = SYLVA_P_REAL,
     .flags = MIN_X | MAX,
     .def = 1,
     .min = 0,
     .max = 1,
     .help = "Normalised age; picks the nearest age variant (1 is full grown)."},
    {.name = "height_above_ground", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0,
     .min = -10000, .max = 10000, .unit = "m",
     .help = "Height of the plant's base above the terrain at [x, y] (a plant on a roof)."},
    {.name = "development", .type = SYLVA_P_BOOL, .def = 0,
     .help = "New planting, part of the development: composited into a photomontage with it, left out "
             "of the existing view."},
};
const host_schema host_schema_plant = {"plants item", "One plant placed by hand.", plant_params,
                                       COUNT(plant_params)};

static const sylva_param_spec plants_file_params[] = {
    {.name = "file", .type = SYLVA_P_PATH, .flags = REQ,
     .help = "An ecology run saved by sylva simulate --save: its plants are placed as the ecology would "
             "place them, without simulating again."},
};
const host_schema host_schema_plants_file = {"plants file", "The plants of a saved ecology run.", plants_file_params,
                                             COUNT(plants_file_params)};

/* --- trees ---------------------------------------------------------------------------------- */
static const sylva_param_spec trees_params[] = {
    {.name = "file", .type = SYLVA_P_PATH, .flags = REQ,
     .help = "The tree survey: a point layer GDAL reads (GeoPackage, Shapefile, GeoJSON, ...) or a CSV "
             "with x and y columns."},
    {.name = "layer", .type = SYLVA_P_STRING,
     .help = "The file's layer holding the trees (default: its only layer)."},
    {.name = "crs", .type = SYLVA_P_STRING,
     .help = "CRS of the file's coordinates, EPSG:NNNN or WKT, in place of the one it states (default: "
             "the file's own, else the site's)."},
    {.name = "x_field", .type = SYLVA_P_STRING, .def_str = "x",
     .help = "CSV column of the easting (or longitude)."},
    {.name = "y_field", .type = SYLVA_P_STRING, .def_str = "y",
     .help = "CSV column of the northing (or latitude)."},
    {.name = "species_field", .type = SYLVA_P_STRING,
     .help = "Attribute holding each tree's species name (default: none, every tree is of `species`)."},
    {.name = "species", .type = SYLVA_P_STRING,
     .help = "Species of a tree whose species is not given or names no species of the scene."},
    {.name = "species_map", .type = SYLVA_P_STRING,
     .help = "The file's species names mapped to the scene's species: {\"Pseudotsuga menziesii\": douglas_fir}."},
    {.name = "height_field", .type = SYLVA_P_STRING, .def_str = "height",
     .help = "Attribute holding each tree's measured height in metres (every tree needs one above 0)."},
    {.name = "crown_field", .type = SYLVA_P_STRING,
     .help = "Attribute holding the crown diameter in metres; the model's crown is stretched to it."},
    {.name = "age_field", .type = SYLVA_P_STRING,
     .help = "Attribute holding the tree's age in years; it picks the age variant, with full_grown_age."},
    {.name = "full_grown_age", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 100, .min = 0, .max = 10000,
     .unit = "years", .help = "Age at which a species' full-grown variant is used (age_field)."},
    {.name = "development", .type = SYLVA_P_BOOL, .def = 0,
     .help = "The trees are a new planting, part of the development (as plants' development)."},
};
const host_schema host_schema_trees = {"trees", "Existing trees from a survey file.", trees_params,
                                       COUNT(trees_params)};

/* --- planting ------------------------------------------------------------------------------ */
const char *const host_stock_sizes[] = {"whip", "feathered", "standard", NULL};
const char *const host_planting_coordinates[] = {"local", "map", NULL};
static const sylva_param_spec planting_item_params[] = {
    {.name = "name", .type = SYLVA_P_STRING,
     .help = "The feature's name in messages (default: blocks[i], belts[i], trees[i] or felling[i])."},
    {.name = "polygon", .type = SYLVA_P_GRID, .unit = "m",
     .help = "A block's or a felling's outline: [[x, y], ...], at least 3 corners, not closed."},
    {.name = "line", .type = SYLVA_P_GRID, .unit = "m",
     .help = "A belt's centre line: [[x, y], ...], at least 2 points."},
    {.name = "position", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 2, .def_list = zero2, .def_len = 2,
     .unit = "m", .help = "A tree's [x, y]."},
    {.name = "species", .type = SYLVA_P_STRING,
     .help = "The scene's species, separated by spaces: a block's mix, a belt's sequence along each row, a tree's one."},
    {.name = "shares", .type = SYLVA_P_LIST, .flags = MIN_X | MAX, .min = 0, .max = 1e6, .max_len = PLANTING_MAX_SPECIES,
     .help = "A block's share of each species, in the order of species (default: equal shares)."},
    {.name = "spacing", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 2, .min = 0, .max = 1000, .unit = "m",
     .help = "Metres between plants: a block's square grid, a belt's plants along a row."},
    {.name = "density", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 2500, .min = 0, .max = 100000, .unit = "1/ha",
     .help = "A block's plants per hectare, in place of spacing."},
    {.name = "rows", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 1, .min = 1, .max = 50,
     .help = "A belt's rows, side by side along its line, staggered."},
    {.name = "row_spacing", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 1.5, .min = 0, .max = 100, .unit = "m",
     .help = "Metres between a belt's rows."},
    {.name = "stock", .type = SYLVA_P_ENUM, .def_str = "whip", .choices = host_stock_sizes,
     .help = "The nursery stock planted: whip (0.6-0.9 m), feathered (1.8-2.4 m) or standard (2.5-3 m)."},
    {.name = "stock_height", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 0.75, .min = 0, .max = 30, .unit = "m",
     .help = "The stock's height at planting, in place of stock (its form then the nearest size's: a whip up to 1.35 m, a feathered tree up to 2.45 m, a standard above, unless stock is given)."},
};
static const sylva_param_spec planting_params[] = {
    {.name = "year", .type = SYLVA_P_REAL, .flags = REQ | MIN | MAX, .min = 0, .max = 10000, .unit = "year",
     .help = "The calendar year of planting; --year N shows the plan N years after it."},
    {.name = "file", .type = SYLVA_P_PATH,
     .help = "The plan drawn in a vector file GDAL reads (GeoPackage, Shapefile, GeoJSON): polygons are blocks (or "
             "fellings, with kind: felling), lines belts, points trees; attributes as the items' keys."},
    {.name = "layer", .type = SYLVA_P_STRING, .help = "The file's layer holding the plan (default: its only one)."},
    {.name = "crs", .type = SYLVA_P_STRING,
     .help = "CRS of the file's coordinates, EPSG:NNNN or WKT, in place of the one it states."},
    {.name = "coordinates", .type = SYLVA_P_ENUM, .def_str = "local", .choices = host_planting_coordinates,
     .help = "What the plan's points are: local metres, or map coordinates (easting, northing) in the site's CRS."},
    {.name = "seed", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 1, .min = 0, .max = 4294967295.0,
     .help = "Seeds where each plant stands, its species and turn: the same plants in the same places every year."},
    {.name = "full_grown_age", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 60, .min = 0, .max = 10000,
     .unit = "years", .help = "Age at which a planted species' full-grown variant stands: the time scale of its growth curve."},
    {.name = "thinning_year", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = 0, .max = 10000,
     .unit = "years", .help = "Years after planting at which blocks and belts are thinned (0: never)."},
    {.name = "thinning_keep", .type = SYLVA_P_REAL, .flags = MIN_X | MAX, .def = 0.5, .min = 0, .max = 1,
     .help = "The share of a block's or belt's plants the thinning keeps."},
    {.name = "ecology", .type = SYLVA_P_BOOL, .def = 1,
     .help = "Blocks' and belts' plants compete and die year by year by the scene's ecology (false: every plant stands, the plan as drawn)."},
    {.name = "maintenance_years", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 5, .min = 0, .max = 10000,
     .unit = "years", .help = "The establishment (defects) period: until then a block's or belt's plant that dies is replaced in kind, so the plan stands whole; the ecology's competition and deaths act from then on."},
    {.name = "age_existing", .type = SYLVA_P_BOOL, .def = 0,
     .help = "The scene's ecology grown on through the plan's years as well: at --year N its plants are N years older (false: they keep their age)."},
    {.name = "blocks", .type = SYLVA_P_GROUP_LIST, .max_len = 100000, .group = planting_item_params,
     .n_group = COUNT(planting_item_params),
     .help = "Woodland blocks: {polygon, species, shares, spacing or density, stock}."},
    {.name = "belts", .type = SYLVA_P_GROUP_LIST, .max_len = 100000, .group = planting_item_params,
     .n_group = COUNT(planting_item_params),
     .help = "Hedgerows and belts: {line, species (the sequence), rows, row_spacing, spacing, stock}."},
    {.name = "trees", .type = SYLVA_P_GROUP_LIST, .max_len = 100000, .group = planting_item_params,
     .n_group = COUNT(planting_item_params),
     .help = "Single trees: {position, species, stock}."},
    {.name = "felling", .type = SYLVA_P_GROUP_LIST, .max_len = 100000, .group = planting_item_params,
     .n_group = COUNT(planting_item_params),
     .help = "Polygons whose existing vegetation is removed: {polygon}."},
};
const host_schema host_schema_planting = {
    "planting", "A planting plan: blocks, belts and trees planted in a stated year, and the vegetation felled.",
    planting_params, COUNT(planting_params)};
const host_schema host_schema_planting_item = {
    "planting item", "One block, belt, tree or felling of a planting plan.", planting_item_params,
    COUNT(planting_item_params)};

/* --- objects -------------------------------------------------------------------------------- */
/* Keys every kind of object has: its name, where it stands and how it is turned, whether it is
 * part of the development, and the CSV layout that places it many times. */
#define OBJECT_COMMON_KEYS                                                                          \
    {.name = "name", .type = SYLVA_P_STRING,                                                        \
     .help = "Label used in messages and in the object-id layer (default: objects[<index>])."},    \
    {.name = "position", .type = SYLVA_P_LIST, .min_len = 2, .max_len = 3, .def_list = zero3,      \
     .def_len = 3, .unit = "m",                                                                     \
     .help = "[x, y, z] of the object's origin, or [x, y] to stand on the terrain."},              \
    {.name = "heading", .type = SYLVA_P_REAL, .flags = MIN | MAX, .def = 0, .min = -360,           \
     .max = 360, .unit = "deg",                                                                     \
     .help = "Compass bearing the object's +Y axis turns to, clockwise from north (+Y)."},         \
    {.name = "height_above_ground", .type = SYLVA_P_REAL, .unit = "m",                             \
     .help = "With a 2-number position: the origin stands this high above the terrain."},          \
    {.name = "development", .type = SYLVA_P_BOOL, .def = 0,                                        \
     .help = "Part of the development: drawn into the EXR's coverage mask layer and the target " \
             "of visibility maps."},                                                                \
    {.name = "development_name", .type = SYLVA_P_STRING,                                           \
     .help = "The development it is part of, when a scene holds several (implies development: "    \
             "true; a cumulative visibility map tells them apart; default 'development')."},      \
    {.name = "layout", .type = SYLVA_P_PATH,                                                       \
     .help = "CSV of placements (id, easting/northing or x/y, heading, height_above_ground): one " \
             "object per row."}

static const sylva_param_spec object_params[] = {
    OBJECT_COMMON_KEYS,
    {.name = "shape", .type = SYLVA_P_ENUM, .flags = REQ, .choices = host_shape_names,
     .help = "Built-in shape: mesh, box, sphere, quad or disk; its keys sit beside this one."},
    {.name = "rotation", .type = SYLVA_P_VEC3, .def_list = zero3, .def_len = 3, .unit = "deg",
     .help = "Rotations about X, then Y, then Z."},
    {.name = "scale", .type = SYLVA_P_VEC3, .flags = MIN_X, .min = 0, .def_list = one3,
     .def_len = 3, .help = "Size factors along X, Y and Z, applied before the rotation."},
    {.name = "material", .type = SYLVA_P_STRING,
     .help = "Material (a name from materials:); the default is a grey lambert."},
};
const host_schema host_schema_object = {"objects item", "A man-made object built from a shape.",
                                        object_params, COUNT(object_params)};

const char *const host_model_up_axes[] = {"file", "y", "z", NULL};

static const sylva_param_spec object_model_params[] = {
    OBJECT_COMMON_KEYS,
    {.name = "model", .type = SYLVA_P_PATH, .flags = REQ,
     .help = "3-D model file: .obj, .gltf, .glb, .ply, .stl, .fbx, .dae or .3ds."},
    {.name = "rotation", .type = SYLVA_P_VEC3, .def_list = zero3, .def_len = 3, .unit = "deg",
     .help = "Rotations of the model about X, then Y, then Z, before the heading."},
    {.name = "scale", .type = SYLVA_P_REAL, .flags = MIN_X, .def = 1, .min = 0, .unit = "m",
     .help = "Metres per model unit, after the file's own unit (0.0254 for a model in inches)."},
    {.name = "up_axis", .type = SYLVA_P_ENUM, .def_str = "file", .choices = host_model_up_axes,
     .help = "Up axis of an OBJ, STL or PLY file (y or z); other formats state their own."},
    {.name = "model_root", .type = SYLVA_P_STRING, /* a folder: PATH names files */
     .help = "Folder that holds the model and every file it refers to (buffers, material "
             "libraries, textures), relative to the scene file; default: the model file's own "
             "folder. References outside it are refused."},
};
const host_schema host_schema_object_model = {
    "objects item with a model", "A man-made object read from a 3-D model file.",
    object_model_params, COUNT(object_model_params)};

static const sylva_param_spec object_group_params[] = {
    OBJECT_COMMON_KEYS,
    {.name = "group", .type = SYLVA_P_STRING, .flags = REQ,
     .help = "Name of a group under groups:, placed as one object."},
};
const host_schema host_schema_object_group = {
    "objects item with a group", "A group's parts placed as one object.", object_group_params,
    COUNT(object_group_params)};

/* --- ecology -------------------------------------------------------------------------------- */
static const sylva_param_spec ecology_params[] = {
    {.name = "plugin", .type = SYLVA_P_STRING, .flags = REQ,
     .help = "Ecology plugin that places the species; its parameters sit beside this key."},
};
const host_schema host_schema_ecology = {
    "ecology", "The plant population: an ecology plugin's block.", ecology_params,
    COUNT(ecology_params)};

/* --- built-in shapes ------------------------------------------------------------------------ */
static const sylva_param_spec box_params[] = {
    {.name = "size",
     .type = SYLVA_P_VEC3,
     .flags = MIN_X,
     .min = 0,
     .def_list = one3,
     .def_len = 3,
     .unit = "m",
     .help = "Edge lengths along X, Y and Z; the box is centred on its origin."},
};
static const sylva_param_spec sphere_params[] = {
    {.name = "radius", .type = SYLVA_P_REAL, .flags = MIN_X, .def = 0.5, .min = 0, .unit = "m",
     .help = "Radius; the sphere is centred on its origin."},
    {.name = "subdivisions", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 3, .min = 0, .max = 7,
     .help = "Icosphere refinement: 20 * 4^subdivisions triangles."},
};
static const sylva_param_spec quad_params[] = {
    {.name = "size", .type = SYLVA_P_LIST, .flags = MIN_X, .min = 0, .min_len = 2, .max_len = 2,
     .def_list = one2, .def_len = 2, .unit = "m",
     .help = "Width along X and height along Y of a rectangle in the XY plane facing +Z."},
};
static const sylva_param_spec disk_params[] = {
    {.name = "radius", .type = SYLVA_P_REAL, .flags = MIN_X, .def = 0.5, .min = 0, .unit = "m",
     .help = "Radius of a disc in the XY plane facing +Z."},
    {.name = "segments", .type = SYLVA_P_INT, .flags = MIN | MAX, .def = 32, .min = 3,
     .max = 4096, .help = "Triangles around the rim."},
};
static const sylva_param_spec mesh_params[] = {
    {.name = "vertices",
     .type = SYLVA_P_GRID,
     .flags = REQ,
     .unit = "m",
     .help = "Vertex positions [[x, y, z], ...]."},
    {.name = "triangles",
     .type = SYLVA_P_GRID,
     .flags = REQ | MIN,
     .min = 0,
     .help = "Triangles as vertex indices from 0 [[i, j, k], ...], counter-clockwise seen from the "
             "front."},
    {.name = "uvs",
     .type = SYLVA_P_GRID,
     .help = "Texture coordinates [[u, v], ...], one per vertex."},
};
const host_schema host_schema_shape_box = {"shape box", "A box.", box_params, COUNT(box_params)};
const host_schema host_schema_shape_sphere = {"shape sphere", "An icosphere.", sphere_params,
                                              COUNT(sphere_params)};
const host_schema host_schema_shape_quad = {"shape quad", "A rectangle.", quad_params,
                                            COUNT(quad_params)};
const host_schema host_schema_shape_disk = {"shape disk", "A flat disc.", disk_params,
                                            COUNT(disk_params)};
const host_schema host_schema_shape_mesh = {"shape mesh", "An inline triangle mesh.",
                                            mesh_params, COUNT(mesh_params)};

const host_schema *host_schema_shape(shape_kind kind)
{
    switch (kind) {
    case SHAPE_BOX: return &host_schema_shape_box;
    case SHAPE_SPHERE: return &host_schema_shape_sphere;
    case SHAPE_QUAD: return &host_schema_shape_quad;
    case SHAPE_DISK: return &host_schema_shape_disk;
    case SHAPE_MESH: return &host_schema_shape_mesh;
    }
    return NULL;
}

const host_schema *host_schema_at(uint32_t i)
{
    static const host_schema *const all[] = {
        &host_schema_image,        &host_schema_site,         &host_schema_position,
        &host_schema_camera,       &host_schema_sun,          &host_schema_sky,
        &host_schema_earth,        &host_schema_ztv,          &host_schema_ztv_target,
        &host_schema_photo,        &host_schema_study,        &host_schema_ground_cover, &host_schema_snow,  &host_schema_landcover,
        &host_schema_canopy,
        &host_schema_material,     &host_schema_terrain,
        &host_schema_species,      &host_schema_phenology,    &host_schema_blossom,      &host_schema_plant,
        &host_schema_plants_file,  &host_schema_trees,        &host_schema_planting,     &host_schema_planting_item,
        &host_schema_ecology,
        &host_schema_object,       &host_schema_object_model, &host_schema_object_group,
        &host_schema_shape_box,    &host_schema_shape_sphere,
        &host_schema_shape_quad,   &host_schema_shape_disk,   &host_schema_shape_mesh};
    return i < COUNT(all) ? all[i] : NULL;
}

const char *host_reserved_key_clash(const sylva_param_spec *params, uint32_t n,
                                    const char *species_section)
{
    for (uint32_t i = 0; i < n; i++) {
        const char *name = params[i].name;
        if (!name) continue;
        if (species_section && !strcmp(name, species_section)) return name;
        for (const char *const *r = plugin_reserved_keys; *r; r++)
            if (!strcmp(name, *r)) return name;
    }
    return NULL;
}
