! Task 2: counts modulo 3 forever and never touches the flag.
MODULE counter
  PERS bool flag := FALSE;
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      n := (n + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
