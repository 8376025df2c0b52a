! expect: RMC101 line 3
MODULE m
  x := 1;
ENDMODULE
