! expect: RMC101 line 3
MODULE m
  TRAP t(num x)
  ENDTRAP
ENDMODULE
