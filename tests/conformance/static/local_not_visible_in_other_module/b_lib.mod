MODULE b_lib
  LOCAL VAR num secret := 42;
ENDMODULE
