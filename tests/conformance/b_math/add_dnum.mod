MODULE MainModule
  ! Tests: Add on a dnum variable keeps double precision.
  PROC main()
    VAR dnum d := 4294967290;
    VAR dnum five := 5;
    Add d, five;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
