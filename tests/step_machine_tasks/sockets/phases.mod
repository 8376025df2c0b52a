! Task 2: moves the phase task 1 reads (also the second task of receive/ and moves/).
MODULE Phases
  PERS num phase := 0;
  PROC main()
    WHILE TRUE DO
      phase := (phase + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
