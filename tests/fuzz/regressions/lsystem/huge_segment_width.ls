recursion 1
angle 30
thickness 8
axiom F(1e308)F
