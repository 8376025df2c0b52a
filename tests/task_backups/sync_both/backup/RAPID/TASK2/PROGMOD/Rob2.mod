MODULE Rob2
  VAR syncident cycle_done;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PERS num cycles2 := 0;
  PROC main()
    WHILE TRUE DO
      IF diSkip = 1 THEN
        TPWrite "robot 2 waits a little longer";
      ENDIF
      cycles2 := (cycles2 + 1) MOD 4;
      WaitSyncTask cycle_done, pair;
    ENDWHILE
  ENDPROC
ENDMODULE
