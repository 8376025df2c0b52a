MODULE array_index_above_error
  ! Tests: writing one element past the end of an array raises ERR_OUTOFBND
  ! (uncaught: exit 1).
  VAR num a{3};
  PROC main()
    FOR i FROM 1 TO 4 DO
      a{i} := i;
      TPWrite "wrote " \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE
