MODULE b_lib
  VAR num counter := 0;
  CONST num LIMIT := 99;
  PROC Bump(num by)
    counter := counter + by;
  ENDPROC
ENDMODULE
