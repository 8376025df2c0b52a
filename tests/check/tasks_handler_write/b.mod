MODULE Failer
  PERS num shared := 0;
  VAR num zero := 0;
  VAR num q := 0;
  PROC main()
    q := 1 DIV zero;
  ERROR
    shared := 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
