! Task 2: moves the data task 1 waits on.
MODULE T2
  PERS num shared := 0;
  PROC main()
    WHILE TRUE DO
      shared := (shared + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
