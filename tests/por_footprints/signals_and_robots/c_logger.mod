MODULE Logger
  VAR num seen := 0;
  PROC main()
    IF diStart = 1 seen := 2;            ! LOCAL
    IF doLamp = 1 THEN                   ! SHARED
      seen := 3;                         ! LOCAL
    ENDIF
  ENDPROC
ENDMODULE
