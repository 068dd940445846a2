axiom F{}
