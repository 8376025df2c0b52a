MODULE Partner
  PERS num note := 0;
  VAR num zero := 0;
  VAR num own := 0;
  VAR num two := 2;
  PROC main()
    own := 1 / zero;
  ERROR
    SetDataVal "note", two;              ! SHARED
    TRYNEXT;
  ENDPROC
ENDMODULE
