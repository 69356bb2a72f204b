# Bends the straight pipe of blockMeshDict: points with 0 <= x <= Lb (the
# middle segment) go onto a 90-degree arc of radius Rb about the z-parallel
# axis through (0, Rb); the outlet segment follows along +y. Cross-sections
# stay planar and circular, so the wall is exactly the torus.
#     awk -v Rb=0.01425 -v Lb=0.02238384 -f bendPoints.awk points
BEGIN { halfPi = atan2(1, 0) }
/^\(-?[0-9.e+-]+ -?[0-9.e+-]+ -?[0-9.e+-]+\)$/ {
    line = $0
    gsub(/[()]/, "", line)
    split(line, p, " ")
    x = p[1] + 0; y = p[2] + 0; z = p[3] + 0
    if (x > 0) {
        s = (x < Lb ? x : Lb)
        theta = s/Lb*halfPi
        r = Rb - y                      # distance from the bend's axis
        X = r*sin(theta)
        Y = Rb - r*cos(theta)
        if (x > Lb) Y += x - Lb         # outlet segment, along +y
        printf "(%.15g %.15g %.15g)\n", X, Y, z
        next
    }
}
{ print }
