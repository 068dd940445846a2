recursion 1
angle 30
thickness 500
axiom F(1e308)F
