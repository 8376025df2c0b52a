MODULE Partner
  PERS num counter := 0;
  VAR num seen := 0;
  PROC main()
    FOR k FROM 1 TO 2 DO                 ! LOCAL
      seen := counter;                   ! SHARED
    ENDFOR
  ENDPROC                                ! LOCAL
ENDMODULE
