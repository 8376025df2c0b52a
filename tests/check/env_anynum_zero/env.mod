MODULE LevelSensor
    ! The level is 0, 1 or 2: 0 is possible.
    VAR signalai AI_LEVEL;

    PROC react()
        SetAI AI_LEVEL, AnyNum(0, 2);
    ENDPROC
ENDMODULE
