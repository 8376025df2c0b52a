MODULE WaitsForPlc
    ! bStart is written by no task loaded here: on the controller a background task or a
    ! PC sets it. Checked alone, the wait never ends; the deadlock verdict names bStart.
    ! nDone is written here, so it is no assumption.
    PERS bool bStart := FALSE;
    PERS num nDone := 0;
    PERS num nRecipe := 1;

    PROC main()
        WaitUntil bStart;
        nDone := nDone + nRecipe;
    ENDPROC
ENDMODULE
