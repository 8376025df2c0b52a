MODULE NumLocalBesideSignals
    ! A routine's num data holding 0 or 1 shows as a number, not as the signal of that
    ! index (doLamp is signal 0, doClamp signal 1): only signal parameters name a signal.
    VAR num parts{2} := [10, 20];

    PROC main()
        SetDO doLamp, 1;
        Pick;
    ENDPROC

    PROC Pick()
        VAR num i := 1;
        VAR num slot := 0;
        SetDO doClamp, 1;
        i := i + 2;
        slot := parts{i};
    ENDPROC
ENDMODULE
