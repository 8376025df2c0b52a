MODULE TeachData
  PERS partdata partA := [120, 80, "box", TRUE];
  PERS gantrygroup jgHome := [[[10,-17,-27.5,0,-45,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
                              [[10,-17,-27.5,0,-45,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
                              [[0,0,0,0,0,0],[8000,2500,0,10,9E9,9E9]]];
ENDMODULE
