MODULE PartFeeder
    ! A part arrives after at most two idle reactions (AnyBool picks when,
    ! idle forces it at the third), stays until the gripper closes on it,
    ! and leaves with the gripper.
    VAR signaldi DI_PART;
    VAR signaldo DO_GRIP;
    VAR num idle := 0;

    PROC init()
        SetDI DI_PART, 0;
    ENDPROC

    PROC react()
        IF DO_GRIP = 1 THEN
            SetDI DI_PART, 0;
        ELSEIF DI_PART = 0 THEN
            IF AnyBool() OR idle >= 2 THEN
                SetDI DI_PART, 1;
                idle := 0;
            ELSE
                idle := idle + 1;
            ENDIF
        ENDIF
    ENDPROC
ENDMODULE
