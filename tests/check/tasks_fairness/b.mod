! Task 2: sets the shared flag over and over; it can always go on.
MODULE b
  PERS bool flag := FALSE;
  PROC main()
    WHILE TRUE DO
      flag := TRUE;
    ENDWHILE
  ENDPROC
ENDMODULE
