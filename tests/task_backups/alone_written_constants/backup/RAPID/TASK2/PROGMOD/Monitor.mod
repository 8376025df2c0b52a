MODULE Monitor
    ! Written for the test (issue 28): the monitor shows whether the robot task is
    ! welding a seam (nStep{1} > 0) and a ratio that needs nStep{1} <> -1.
    PERS num nStep{2};
    VAR num nRatio := 0;

    PROC main()
        WHILE TRUE DO
            IF nStep{1} > 0 THEN
                TPWrite "welding";
            ENDIF
            nRatio := 100 / (nStep{1} + 1);
            WaitTime 0.1;
        ENDWHILE
    ENDPROC
ENDMODULE
