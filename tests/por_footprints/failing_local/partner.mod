MODULE Partner
  PERS bool flag := FALSE;
  PERS bool seen := FALSE;
  PROC main()
    WaitUntil flag;                      ! SHARED
    seen := TRUE;                        ! VISIBLE
  ENDPROC
ENDMODULE
