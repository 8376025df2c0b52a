! The main task waits for a flag that nobody sets.
MODULE prog
  PERS bool flag := FALSE;
  VAR bool seen := FALSE;
  PROC main()
    WaitUntil flag;
    seen := TRUE;
  ENDPROC
ENDMODULE
