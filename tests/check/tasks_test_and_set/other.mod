! Task 2 takes the lock with TestAndSet, trying again until it gets it.
MODULE other
  PERS bool lock := FALSE;
  PERS num inside := 0;
  PERS num uses := 0;
  PROC main()
    FOR i FROM 1 TO 2 DO
      WHILE NOT TestAndSet(lock) DO
      ENDWHILE
      inside := inside + 1;
      uses := uses + 1;
      inside := inside - 1;
      lock := FALSE;
    ENDFOR
  ENDPROC
ENDMODULE
