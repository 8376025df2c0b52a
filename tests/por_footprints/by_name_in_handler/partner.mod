MODULE Partner
  PERS num note := 0;
  VAR num zero := 0;
  VAR num q := 0;
  PROC main()
    q := 1 DIV zero;                     ! LOCAL
  ERROR
    SetDataVal "note", 2;                ! SHARED
    TRYNEXT;
  ENDPROC
ENDMODULE
