#!/usr/bin/env python3
"""steep_dry_dtm.py OUT.asc — a steep, dry foothill DTM like the San Gabriel front above Big
Tujunga (34.3 N): 200 x 200 nodes 30 m apart in NAD83 / UTM zone 11N (EPSG:26911), heights 600
to 2,000 m, ridges and ravines whose sides slope mostly 30 to 40 degrees. Writes OUT.asc and
OUT.prj (ESRI ASCII grid). Deterministic: no random numbers."""
import math
import sys

N, CELL = 200, 30.0
X0, Y0 = 380000.0, 3795000.0  # lower-left corner, UTM 11N: near 34.29 N, 118.30 W
WAVE = 2400.0                 # m between ridges

def height(x, y):
    rise = 1000.0 * y / ((N - 1) * CELL)             # the range front climbs northward
    ridges = 170.0 * (1 + math.sin(2 * math.pi * x / WAVE + 0.6 * math.sin(2 * math.pi * y / 3100.0)))
    spurs = 45.0 * math.sin(2 * math.pi * (x + y) / 900.0)
    return 600.0 + rise + ridges + spurs + 90.0

def main(path):
    with open(path, "w") as f:
        f.write(f"ncols {N}\nnrows {N}\nxllcorner {X0}\nyllcorner {Y0}\ncellsize {CELL}\nNODATA_value -9999\n")
        for row in range(N):
            y = (N - 1 - row) * CELL
            f.write(" ".join(f"{min(2000.0, height(c * CELL, y)):.1f}" for c in range(N)) + "\n")
    with open(path[:-4] + ".prj", "w") as f:
        f.write('PROJCS["NAD83 / UTM zone 11N",GEOGCS["NAD83",DATUM["North_American_Datum_1983",'
                'SPHEROID["GRS 1980",6378137,298.257222101]],PRIMEM["Greenwich",0],'
                'UNIT["degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],'
                'PARAMETER["latitude_of_origin",0],PARAMETER["central_meridian",-117],'
                'PARAMETER["scale_factor",0.9996],PARAMETER["false_easting",500000],'
                'PARAMETER["false_northing",0],UNIT["metre",1],AUTHORITY["EPSG","26911"]]\n')

if __name__ == "__main__":
    main(sys.argv[1])
