/* scene_file_photo.c — the photo: section: the photograph of a photomontage, its control points
 * and what the camera match may change. */
#include "scene_file/scene_file_loader.h"

int sf_read_photo(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "photo");
    if (!pr) return 0;
    photo_settings *ph = &L->sf->photo;
    ph->line = pr->key_line, ph->column = pr->key_column;
    param_scope scope = {L->file, L->dir, "photo", NULL, 0, pr->key_line, pr->key_column};
    const sylva_params *p;
    if (params_validate(L->a, pr->value, host_schema_photo.params, host_schema_photo.n_params, &scope, &p, L->err))
        return -1;
    ph->file = sylva_param(p, "file")->s;
    const sylva_value *cp = sylva_param(p, "control_points");
    ph->control_points = cp->is_set ? cp->s : NULL;
    ph->sensor_width_mm = sylva_param_real(p, "sensor_width");
    ph->focal_length_mm = sylva_param_real(p, "focal_length");
    ph->fit_position = (int)sylva_param(p, "fit_position")->i;
    ph->fit_focal_length = (int)sylva_param(p, "fit_focal_length")->i;
    ph->fit_distortion = (int)sylva_param(p, "fit_distortion")->i;
    ph->camera_from_exif = (int)sylva_param(p, "camera_from_exif")->i;
    if (ph->camera_from_exif && !L->sf->site.crs_wkt) {
        const sylva_value *v = sylva_param(p, "camera_from_exif");
        return sf_located(L->err, L->file, v->line, v->column,
                          "'camera_from_exif' places the camera at the photograph's GPS position, which needs a "
                          "site: section to put longitude and latitude on the map");
    }
    ph->exposure = sylva_param_real(p, "exposure");
    return 0;
}
