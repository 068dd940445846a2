/* ztv_qml.h — QGIS styles (QML) for what `sylva ztv` writes, so that the map opens in QGIS as
 * sylva draws it (docs/ztv.md, "QGIS"): the viewpoints numbered, the distance rings dashed and
 * labelled, the development's structures named, and the visibility GeoTIFF's fraction band in
 * the map's six colours. The texts are constant; nothing here allocates. */
#ifndef SYLVA_ZTV_QML_H
#define SYLVA_ZTV_QML_H

typedef enum ztv_qml_style {
    ZTV_QML_VIEWPOINTS = 0,   /* the GeoPackage's viewpoints layer */
    ZTV_QML_RINGS = 1,        /* its distance_rings layer */
    ZTV_QML_DEVELOPMENTS = 2, /* its developments layer */
    ZTV_QML_VISIBILITY = 3,   /* ztv_MODE.tif: band 2, the fraction of the targets visible */
    ZTV_QML_STYLES = 4
} ztv_qml_style;

/* The style's QML document (static text). */
const char *ztv_qml_text(ztv_qml_style style);
/* The name QGIS lists it under ("sylva viewpoints", ...). */
const char *ztv_qml_name(ztv_qml_style style);

#endif
