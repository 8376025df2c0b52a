MODULE Partner
  PERS num speed := 100;
  PROC main()
    speed := 50;                                   ! SHARED
    speed := speed + 1;                            ! SHARED
  ENDPROC
ENDMODULE
