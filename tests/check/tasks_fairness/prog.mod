! The main task waits for the flag that task 2 (b.mod) keeps setting, notes it and clears it.
MODULE prog
  PERS bool flag := FALSE;
  VAR bool seen := FALSE;
  PROC main()
    WHILE TRUE DO
      WaitUntil flag;
      seen := TRUE;
      flag := FALSE;
      seen := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
