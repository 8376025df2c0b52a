MODULE Unused
  VAR num used_counter := 0;
  VAR num spare := 0;  ! expect: RMC806
  LOCAL VAR bool old_flag := FALSE;  ! expect: RMC806
  PERS num shared_with_other_task := 0;
  VAR intnum timer;

  PROC main()
    VAR num scratch;  ! expect: RMC806
    used_counter := used_counter + 1;
    CONNECT timer WITH OnTimer;
    ITimer 1, timer;
    CallByVar "station", 1;
    Helper;
  ENDPROC

  PROC Helper()
    TPWrite "help";
  ENDPROC

  PROC Forgotten(num times)  ! expect: RMC807
    TPWrite "nobody calls me";
  ENDPROC

  ! A global procedure without parameters nobody calls: an operator may start it from
  ! the FlexPendant (PP to routine), no finding.
  PROC ServicePosition()
    TPWrite "service";
  ENDPROC

  PROC station1()
    TPWrite "called by CallByVar";
  ENDPROC

  TRAP OnTimer
    used_counter := 0;
  ENDTRAP
ENDMODULE
