MODULE Partner
  PERS num cycles := 0;
  PERS num hits := 0;
  PERS bool done := FALSE;
  VAR num seen := 0;
  PROC main()
    FOR i FROM 1 TO 3 DO                 ! LOCAL
      hits := hits + 1;                  ! LOCAL
    ENDFOR
    WaitUntil done;                      ! SHARED
    seen := 1;                           ! VISIBLE
  ENDPROC
ENDMODULE
