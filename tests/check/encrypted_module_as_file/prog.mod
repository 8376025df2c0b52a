MODULE Cell
  ! The license module LicTool.sys is encrypted (as a licensed add-in ships it): rapidmc
  ! leaves it out, declares what this module uses from it (LicInit, licReady, licMode)
  ! from the uses, and reads its PERS as data written from outside.
  VAR num slot;
  VAR num parts{3};

  PROC main()
    LicInit;
    ! written by the encrypted module: no deadlock
    WaitUntil licReady;
    IF licMode = 2 THEN
      slot := 1;
    ENDIF
    ! any other mode leaves slot 0: ERR_OUTOFBND stays found
    parts{slot} := 5;
  ENDPROC
ENDMODULE
