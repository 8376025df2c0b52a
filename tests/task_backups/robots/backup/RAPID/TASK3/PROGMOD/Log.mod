MODULE Log
  PERS num done := 0;
  VAR num seen := 0;
  PROC log_main()
    WaitUntil done = 1;
    seen := 1;
  ENDPROC
ENDMODULE
