/* proj_network.h — PROJ's own network access (transformation grids fetched from a CDN) shut
 * for the whole process unless the command line allows the network (--allow-gdal-virtual).
 *
 * PROJ enables it from the environment (PROJ_NETWORK=ON) or from a proj.ini found through
 * PROJ_DATA / PROJ_LIB (network = on), and GDAL makes PROJ contexts of its own (one per thread,
 * for every coordinate transformation, such as the warper's), which site_frame's context
 * settings never reach. proj_network_start, run once at start-up, turns it off for every
 * context GDAL has made or will make (OSRSetPROJEnableNetwork) and for every context made
 * directly through PROJ (PROJ_NETWORK=OFF in the environment, which outranks proj.ini). */
#ifndef SYLVA_PROJ_NETWORK_H
#define SYLVA_PROJ_NETWORK_H

/* Shuts PROJ's network access, remembering what the environment asked for. */
void proj_network_start(void);
/* allow 1: gives back what the environment asked for (the user allowed the network); 0: shut
 * again. Call after proj_network_start. */
void proj_network_allow(int allow);
/* 1 when a PROJ context made now, by GDAL or directly, would reach the network. */
int proj_network_enabled(void);

#endif
