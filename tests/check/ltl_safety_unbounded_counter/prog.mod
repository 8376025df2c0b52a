MODULE SafetyCounter
    ! A cell's main loop counts its cycles and never stops: no state repeats, so no
    ! accepting cycle ever closes after the bad state.  In cycle 3 the gripper opens
    ! while the arm moves (the defect the property is about).
    VAR num nCount := 0;
    VAR bool gripper_open := FALSE;
    VAR bool moving := FALSE;

    PROC main()
        WHILE TRUE DO
            moving := TRUE;
            IF nCount = 3 THEN
                gripper_open := TRUE;
            ENDIF
            moving := FALSE;
            gripper_open := FALSE;
            nCount := nCount + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
