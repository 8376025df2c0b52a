! expect: RMC105 line 6
MODULE m
  PROC p()
    count := count + 1;
    count := count + 1;
    a_name_that_is_much_too_long_for_rapid := count;
    a_name_that_is_much_too_long_for_rapid := count;
  ENDPROC
ENDMODULE
