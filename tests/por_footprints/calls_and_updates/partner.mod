MODULE Partner
  PERS num counter := 0;
  PERS num handed := 0;
  VAR num own := 0;
  PROC main()
    FOR k FROM 1 TO 2 DO                 ! LOCAL
      Incr own;                          ! LOCAL
      handed := own;                     ! SHARED
      counter := 0;                      ! SHARED
    ENDFOR
  ENDPROC                                ! LOCAL
ENDMODULE
