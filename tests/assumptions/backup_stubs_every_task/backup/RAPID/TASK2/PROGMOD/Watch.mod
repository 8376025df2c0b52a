MODULE Watch
    PERS bool bReady := FALSE;
    PROC main()
        WaitUntil bReady;
        ! an option routine too (BullsEye), in the other task
        BeScan 1;
    ENDPROC
ENDMODULE
