axiom c(0e400)F
