! expect: RMC104 line 3
MODULE m
  CONST num big := 1E999;
ENDMODULE
