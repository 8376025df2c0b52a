! expect: RMC105 line 3
MODULE m
  VAR num a_name_that_is_much_too_long_for_rapid;
ENDMODULE
