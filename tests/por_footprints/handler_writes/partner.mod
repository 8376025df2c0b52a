MODULE Partner
  PERS num note := 0;
  VAR num zero := 0;
  VAR num own := 0;
  PROC main()
    own := 1 / zero;
  ERROR
    note := 2;                           ! SHARED
    TRYNEXT;
  ENDPROC
ENDMODULE
