! expect: RMC101 line 3
MODULE m
  VAR num a, b;
ENDMODULE
