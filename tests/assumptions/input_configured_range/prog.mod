MODULE GantryDistance
    ! A gantry's measured position (aiGantryX) against the position this task commands
    ! (aoGantryX): their difference is compared with a distance, so the input has no exact
    ! default. It takes 0, the number 50 and their neighbours, and the ends EIO.cfg
    ! configures (-1000 and 1000), nothing beyond them.
    VAR num distance := 0;

    PROC main()
        SetAO aoGantryX, 200;
        distance := Abs(AOutput(aoGantryX) - AInput(aiGantryX));
        IF distance < 50 THEN
            SetDO doTooClose, 1;
        ELSE
            SetDO doTooClose, 0;
        ENDIF
    ENDPROC
ENDMODULE
